#ifndef pg_mesh_particle_set_h
#define pg_mesh_particle_set_h

#include <pg/base/global.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>

#include <array>
#include <map>
#include <vector>

namespace pg
{
  /**
   * The particles: the vertices of the meshfree cells ("collocated FE
   * nodes", pg-methods.md section 5.1). A particle's displacement is the Q1
   * nodal displacement of its vertex, so particles share their DoFs with
   * the Q1 cells at the FE/meshfree interface (architecture.md section 1).
   *
   * Particles are numbered in the order of their vertex indices, which is
   * the same on every MPI rank.
   */
  template <int dim>
  class ParticleSet
  {
  public:
    /**
     * Collect the particles of the cells marked in @p meshfree (indexed by
     * active_cell_index) of @p dof_handler, whose finite element must be
     * FESystem(FE_Q(1), dim), or on the meshfree cells FESystem(FE_Q(1)^dim,
     * FE_Q(1)^n) with n extra nodal fields (dofs/field_layout.h). Computes the
     * lumped volumes V^k = sum over meshfree cells of the integral of N_k, the
     * local spacing, and the geometric area vectors of the boundary parts.
     */
    void
    reinit(const DoFHandler<dim>   &dof_handler,
           const std::vector<bool> &meshfree);

    /**
     * As above with the mirror symmetry planes of the boundary ids
     * @p mirror_ids ('Symmetry treatment = mirror'): their faces are no
     * boundary (no area vectors, no corners or edges there), a particle's
     * spacing counts the mirrored cell edges, and the particles on a
     * plane are recorded (on_mirror_planes()). Each plane must be normal
     * to a coordinate axis, and no two planes parallel; throws
     * ExcBadParameter naming 'Boundary conditions/Symmetry treatment'
     * otherwise. Call add_mirror_images() next.
     */
    void
    reinit(const DoFHandler<dim>                 &dof_handler,
           const std::vector<bool>               &meshfree,
           const std::vector<types::boundary_id> &mirror_ids);

    /**
     * Add the mirror image of every particle within @p reach (length, the
     * largest horizon) of one, two or three of the mirror planes, across
     * each combination of them that moves it (at most 2^planes - 1
     * images). Images are numbered from n_particles() on; they are family
     * members only: position(), spacing() and dof() take their indices
     * (dof() gives the original's DoF, mirror_sign() the sign of its
     * component), volume() does not (member_volume()).
     */
    void
    add_mirror_images(const double reach);

    /** The real particles (images not counted). */
    unsigned int
    n_particles() const;

    /** Real particles and their mirror images. */
    unsigned int
    n_particles_and_images() const;

    /** The number of mirror planes (0 without 'Symmetry treatment = mirror').
     */
    unsigned int
    n_mirror_planes() const;

    /** The coordinate axis to which mirror plane @p p is normal. */
    unsigned int
    mirror_plane_axis(const unsigned int p) const;

    /** The coordinate of mirror plane @p p along its axis (length). */
    double
    mirror_plane_offset(const unsigned int p) const;

    /** The particle whose image @p j is (j itself for a real particle). */
    unsigned int
    original(const unsigned int j) const;

    /** The mirror planes across which image @p j lies (bit p: plane p). */
    unsigned int
    mirror_mask(const unsigned int j) const;

    /** The mirror planes real particle @p k lies on (bit p: plane p). */
    unsigned int
    on_mirror_planes(const unsigned int k) const;

    /**
     * The image of real particle @p k across the planes @p mask: k itself
     * for the planes that k lies on. Throws ExcInternalError if that image
     * was not made (beyond the reach of add_mirror_images()).
     */
    unsigned int
    mirror_image(const unsigned int k, const unsigned int mask) const;

    /**
     * The particle or image at the reflection of particle or image @p j
     * across the planes @p mask, or numbers::invalid_unsigned_int if that
     * image was not made (it then lies farther than the reach of
     * add_mirror_images() from a plane, beyond every horizon of the model's
     * particles).
     */
    unsigned int
    reflection(const unsigned int j, const unsigned int mask) const;

    /**
     * +1, or -1 for a displacement component @p c < dim of an image
     * across a plane normal to axis c: u_c(image) = mirror_sign(j, c)
     * u_c(original(j)). Extra nodal fields (pressure) are even: +1.
     */
    double
    mirror_sign(const unsigned int j, const unsigned int c) const;

    /**
     * The volume of particle or image @p j as a family member: the lumped
     * volume in the body that the mirror planes complete (2^m volume() for
     * a particle on m planes), volume() without mirror planes.
     */
    double
    member_volume(const unsigned int j) const;

    /**
     * The share of the family of real particle @p k in the model: volume()
     * over member_volume(), 1/2^m for a master on m mirror planes (its
     * family is its own mirror image, shared with the mirrored body), 1
     * elsewhere. The weights of the family's elements carry it.
     */
    double
    family_share(const unsigned int k) const;

    /**
     * @p v without its components normal to the mirror planes that real
     * particle @p k lies on: the part of a row of particle k that the
     * symmetry does not fix (the normal part of its unit-stress residual
     * is the other half's, like a reaction).
     */
    Tensor<1, dim>
    parallel_to_mirror_planes(const unsigned int    k,
                              const Tensor<1, dim> &v) const;

    /** Reference position X^k. */
    const Point<dim> &
    position(const unsigned int k) const;

    /** Lumped volume V^k (volume units). */
    double
    volume(const unsigned int k) const;

    /** Mean length of the meshfree cell edges at particle k. */
    double
    spacing(const unsigned int k) const;

    /**
     * The global DoF of component @p c of particle k: c < dim the
     * displacement, c = dim + f the extra nodal field f (the pressure and
     * the dilatation of U2P1C and Unl+P1C).
     */
    types::global_dof_index
    dof(const unsigned int k, const unsigned int c) const;

    /** dim plus the number of extra nodal fields of the particles. */
    unsigned int
    n_components() const;

    /** Global vertex index of particle k. */
    unsigned int
    vertex(const unsigned int k) const;

    /**
     * Geometric area vectors of particle k, one per boundary id:
     * a^k_b = integral of N_k n over the meshfree faces with id b.
     * Empty for interior particles.
     */
    const std::map<types::boundary_id, Tensor<1, dim>> &
    boundary_area_vectors(const unsigned int k) const;

    /**
     * Whether the boundary faces at particle k have normals that differ by
     * more than 30 degrees (an edge or a corner of the body), where a nodal
     * normal is ambiguous.
     */
    bool
    at_corner(const unsigned int k) const;

    /**
     * 3-D: for a particle at an edge of the body, where the boundary faces
     * at particle k fall into two groups of normals more than 30 degrees
     * apart (at_corner()) but every face normal lies within 30 degrees of
     * the plane of the two most different ones, the unit direction of the
     * edge (normal to that plane). Zero elsewhere: interior and smooth
     * surface particles, corners where three or more faces meet, and
     * always in 2-D.
     */
    const Tensor<1, dim> &
    edge_direction(const unsigned int k) const;

    /** Whether particle k is also a vertex of a finite element cell. */
    bool
    on_interface(const unsigned int k) const;

    /**
     * Area vector of particle k on the FE/meshfree interface: the integral
     * of N_k n over the faces between meshfree and finite element cells,
     * with n pointing out of the meshfree region. Zero away from it.
     */
    const Tensor<1, dim> &
    interface_area_vector(const unsigned int k) const;

    /** Sum of all particle volumes. */
    double
    total_volume() const;

  private:
    /** A mirror plane X[axis] = offset of the boundary id. */
    struct MirrorPlane
    {
      unsigned int       axis;
      double             offset;
      types::boundary_id boundary_id;
    };
    std::vector<MirrorPlane> mirror_planes;
    /** Real particles. */
    unsigned int n_real = 0;
    /** Per real particle: the planes it lies on. */
    std::vector<unsigned int> plane_masks;
    /** Per image (index - n_real): its original and its planes. */
    std::vector<unsigned int> image_originals, image_masks;
    /** Per real particle and mask: the image (invalid if not made). */
    std::vector<std::array<unsigned int, 8>> image_indices;

    std::vector<Point<dim>>                                   positions;
    std::vector<double>                                       volumes;
    std::vector<double>                                       spacings;
    std::vector<std::array<types::global_dof_index, dim + 2>> dofs;
    unsigned int                                              components = dim;
    std::vector<unsigned int>                                 vertices;
    std::vector<std::map<types::boundary_id, Tensor<1, dim>>> area_vectors;
    std::vector<bool>                                         interface;
    std::vector<bool>                                         corner;
    std::vector<Tensor<1, dim>>                               edges;
    std::vector<Tensor<1, dim>>                               interface_areas;
  };
} // namespace pg

#endif
