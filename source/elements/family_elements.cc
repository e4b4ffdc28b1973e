#include <pg/base/exceptions.h>
#include <pg/base/parallel_for.h>
#include <pg/elements/family_elements.h>
#include <pg/shape_functions/correction_functions.h>

#include <algorithm>
#include <sstream>

namespace pg
{
  template <int dim>
  FamilyElements<dim>::FamilyElements(const ParticleSet<dim>    &particles,
                                      const FamilySet<dim>      &families,
                                      const FormulationCode     &formulation,
                                      const ShapeFunctions::Base base,
                                      const double weight_exponent)
    : particles(particles)
    , families(families)
    , formulation(formulation)
    , base(formulation.points == FormulationCode::Points::u2 ?
             ShapeFunctions::Base::wte2 :
             base)
    , weight_exponent(weight_exponent)
  {}



  template <int dim>
  ShapeFunctions::FamilyGeometry<dim>
  FamilyElements<dim>::geometry(const unsigned int k) const
  {
    ShapeFunctions::FamilyGeometry<dim> g;
    const auto                          members = families.members(k);
    g.bonds.resize(members.size());
    g.volumes.resize(members.size());
    for (unsigned int i = 0; i < members.size(); ++i)
      {
        g.bonds[i] =
          particles.position(members[i]) - particles.position(members[0]);
        g.volumes[i] = particles.member_volume(members[i]);
      }
    g.weight_exponent = weight_exponent;
    return g;
  }



  template <int dim>
  void
  FamilyElements<dim>::checked_gradients(
    const unsigned int                         k,
    const ShapeFunctions::FamilyGeometry<dim> &geometry,
    const unsigned int                         point,
    std::vector<Tensor<1, dim>>               &g) const
  {
    const double cond = ShapeFunctions::raw_gradients(base, geometry, point, g);
    if (!(cond <= maximum_condition_number))
      {
        std::ostringstream where, detail;
        where << "(" << particles.position(k) << ")";
        detail << " (condition number " << cond << " > "
               << maximum_condition_number << " at member "
               << families.members(k)[point] << " at ("
               << particles.position(families.members(k)[point]) << "))";
        AssertThrow(false,
                    ExcSingularFamily(k,
                                      where.str(),
                                      families.n_neighbours(k),
                                      detail.str()));
      }
  }



  template <int dim>
  void
  FamilyElements<dim>::initialize(const std::vector<bool> &needed)
  {
    Assert(needed.empty() || needed.size() == families.n_families(),
           ExcDimensionMismatch(needed.size(), families.n_families()));
    const auto is_needed = [&](const unsigned int k) {
      return needed.empty() || needed[k];
    };
    master.assign(families.n_families(), {});
    parallel_for_each_index(families.n_families(), [&](const unsigned int k) {
      if (is_needed(k))
        {
          checked_gradients(k, geometry(k), 0, master[k]);
          ShapeFunctions::make_effective(master[k]);
        }
    });
    // PBG tests with its trial functions: no copy (memory, all families)
    master_test.clear();
    if (formulation.method != FormulationCode::Method::pbg)
      master_test = master;
    alpha.clear();
    phi.clear();
    if (formulation.variational_consistency)
      {
        phi.resize(families.n_families());
        parallel_for_each_index(families.n_families(),
                                [&](const unsigned int k) {
                                  if (is_needed(k))
                                    checked_correction_function(k,
                                                                geometry(k),
                                                                phi[k]);
                                });
      }
  }



  template <int dim>
  void
  FamilyElements<dim>::check_family(const unsigned int k,
                                    const bool         master_only) const
  {
    const ShapeFunctions::FamilyGeometry<dim> geom = geometry(k);
    std::vector<Tensor<1, dim>>               g;
    // build() of PBG U1 uses the master only; PPG skips it (j != k)
    const bool u1 = (formulation.method == FormulationCode::Method::pbg &&
                     formulation.points == FormulationCode::Points::u1);
    const unsigned int n_points =
      (master_only || u1) ? 1 : families.members(k).size();
    for (unsigned int point = 0; point < n_points; ++point)
      checked_gradients(k, geom, point, g);
    if (master_only && formulation.variational_consistency)
      checked_correction_function(k, geom, g);
  }



  template <int dim>
  void
  FamilyElements<dim>::checked_correction_function(
    const unsigned int                         k,
    const ShapeFunctions::FamilyGeometry<dim> &geometry,
    std::vector<Tensor<1, dim>>               &values) const
  {
    const double cond =
      ShapeFunctions::correction_function(family_correction_function(k),
                                          geometry,
                                          values);
    if (!(cond <= maximum_condition_number))
      {
        std::ostringstream where, detail;
        where << "(" << particles.position(k) << ")";
        detail << " for the fit of the VC correction function (condition "
                  "number "
               << cond << " > " << maximum_condition_number
               << "; V2/V4 fit a quadratic (WLS2) and need at least "
               << (dim == 2 ? 6 : 10) << " neighbours not on one conic)";
        AssertThrow(false,
                    ExcSingularFamily(k,
                                      where.str(),
                                      families.n_neighbours(k),
                                      detail.str()));
      }
  }



  template <int dim>
  FormulationCode::CorrectionFunction
  FamilyElements<dim>::family_correction_function(const unsigned int k) const
  {
    // PPG corrects only its test functions, which need no consistency
    // (section 5.3.2), so the correction function is free there. With V3
    // (V2, V4, V5: an MLS fit evaluated at the master) on the one-sided
    // families of interface masters, the VC system is nearly singular
    // where the FE/meshfree interface meets a surface with option sn: on
    // the plate with a hole, particles to 3R, max |alpha^k| h is 89 at
    // refinement 4 and 330 at 5 at that corner, against 2 elsewhere, and
    // the energy error does not converge. The constant V1 at interface
    // masters keeps max |alpha^k| h below 2 (doc/ambiguities.md). PBG
    // corrects its trial functions too, which V1 would make inconsistent:
    // it keeps the chosen function.
    if (particles.on_interface(k) &&
        (formulation.method == FormulationCode::Method::ppg1 ||
         formulation.method == FormulationCode::Method::ppg2))
      return FormulationCode::CorrectionFunction::v1;
    return formulation.correction_function;
  }



  template <int dim>
  Tensor<2, dim>
  FamilyElements<dim>::projector(
    const ShapeFunctions::FamilyGeometry<dim> &geometry,
    const unsigned int                         point) const
  {
    Tensor<2, dim> Q = unit_symmetric_tensor<dim>();
    if (formulation.correction_function ==
          FormulationCode::CorrectionFunction::v5 &&
        point != 0)
      {
        const Tensor<1, dim> &b = geometry.bonds[point];
        Q -= outer_product(b, b) / b.norm_square();
      }
    return Q;
  }



  template <int dim>
  Tensor<1, dim>
  FamilyElements<dim>::correction(
    const unsigned int                         k,
    const ShapeFunctions::FamilyGeometry<dim> &geometry,
    const unsigned int                         point,
    const unsigned int                         a) const
  {
    return diagonal(phi[k][a]) * (projector(geometry, point) * alpha[k]);
  }



  template <int dim>
  void
  FamilyElements<dim>::set_correction_factors(
    const std::vector<Tensor<1, dim>> &factors,
    const std::vector<Tensor<2, dim>> &second_order_factors)
  {
    Assert(formulation.variational_consistency, ExcInternalError());
    AssertDimension(factors.size(), families.n_families());
    Assert(second_order_factors.empty() ||
             (formulation.second_order_consistency &&
              second_order_factors.size() == families.n_families()),
           ExcInternalError());
    alpha = factors;
    // The master gradients: PPG corrects its test functions only, PBG the
    // common trial and test functions (at the master Q = 1). VC2 adds
    // phi^{ka} alpha_2^k dX^{ka} (section 11.6: the bond to the node).
    for (unsigned int k = 0; k < families.n_families(); ++k)
      {
        const auto geom = second_order_factors.empty() ?
                            ShapeFunctions::FamilyGeometry<dim>() :
                            geometry(k);
        // families this rank does not need have no data (initialize())
        for (unsigned int a = 0; a < master[k].size(); ++a)
          {
            Tensor<1, dim> c = diagonal(phi[k][a]) * alpha[k];
            if (!second_order_factors.empty()) // V1, V3: phi is a scalar
              c += phi[k][a][0] * (second_order_factors[k] * geom.bonds[a]);
            if (formulation.method == FormulationCode::Method::pbg)
              master[k][a] += c;
            else
              master_test[k][a] = master[k][a] + c;
          }
      }
  }



  template <int dim>
  const std::vector<Tensor<1, dim>> &
  FamilyElements<dim>::correction_function_values(const unsigned int k) const
  {
    AssertIndexRange(k, phi.size());
    Assert(!phi[k].empty(),
           ExcMessage("Family data not computed on this rank (initialize())."));
    return phi[k];
  }



  template <int dim>
  const std::vector<Tensor<1, dim>> &
  FamilyElements<dim>::master_gradients(const unsigned int k) const
  {
    AssertIndexRange(k, master.size());
    Assert(!master[k].empty(),
           ExcMessage("Family data not computed on this rank (initialize())."));
    return master[k];
  }



  template <int dim>
  const std::vector<Tensor<1, dim>> &
  FamilyElements<dim>::master_test_gradients(const unsigned int k) const
  {
    if (formulation.method == FormulationCode::Method::pbg)
      return master_gradients(k);
    AssertIndexRange(k, master_test.size());
    Assert(!master_test[k].empty(),
           ExcMessage("Family data not computed on this rank (initialize())."));
    return master_test[k];
  }



  template <int dim>
  void
  FamilyElements<dim>::build_master_table(const unsigned int    k,
                                          QuadratureTable<dim> &table) const
  {
    // Test = trial = the (VC-corrected) test gradients: see the
    // declaration.
    const auto &gradients = master_test_gradients(k);
    const bool  substituted_v1 =
      (family_correction_function(k) != formulation.correction_function);
    table.reinit(gradients.size(), !substituted_v1);
    if (!substituted_v1)
      {
        table.add_point(particles.volume(k), gradients, particles.position(k));
        return;
      }
    // pg's V1 at an interface master: the trial gradients M^{-T} G with
    // M = sum_b dX^b (x) G^b, so that F^{kk} of a linear field stays exact.
    const auto     bonds = geometry(k).bonds;
    Tensor<2, dim> M;
    for (unsigned int b = 0; b < gradients.size(); ++b)
      M += outer_product(bonds[b], gradients[b]);
    const Tensor<2, dim>        M_inv_T = transpose(invert(M));
    std::vector<Tensor<1, dim>> trial(gradients.size());
    for (unsigned int b = 0; b < gradients.size(); ++b)
      trial[b] = M_inv_T * gradients[b];
    table.add_point(particles.volume(k), trial, particles.position(k));
    for (unsigned int a = 0; a < gradients.size(); ++a)
      table.add_test_vector(a, gradients[a]);
  }



  template <int dim>
  void
  FamilyElements<dim>::build(const unsigned int    k,
                             QuadratureTable<dim> &table) const
  {
    using Method                                      = FormulationCode::Method;
    const auto                                members = families.members(k);
    const unsigned int                        n       = members.size();
    const ShapeFunctions::FamilyGeometry<dim> geom    = geometry(k);
    std::vector<Tensor<1, dim>>               g;

    // Effective trial gradients of family k at its member j.
    const bool corrected = !alpha.empty();
    const auto trial_at  = [&](const unsigned int j) {
      checked_gradients(k, geom, j, g);
      if (formulation.bond_correction && j != 0)
        ShapeFunctions::apply_bond_correction(geom, j, g);
      ShapeFunctions::make_effective(g);
      // PBG: test = trial, both VC-corrected (eq. 5.56)
      if (corrected && formulation.method == Method::pbg)
        for (unsigned int a = 0; a < n; ++a)
          g[a] += correction(k, geom, j, a);
    };

    if (formulation.method == Method::pbg)
      {
        table.reinit(n, true);
        table.trial.reserve(
          (formulation.points == FormulationCode::Points::u1 ? 1 : n) * n);
        double family_volume = 0;
        for (const double v : geom.volumes)
          family_volume += v;
        // the family's share of the model: V^k / its member volume (1/2^m
        // for a master on m mirror planes, whose family is its own image)
        const double share = particles.family_share(k);
        if (formulation.points == FormulationCode::Points::u1)
          table.add_point(share * geom.volumes[0],
                          master[k],
                          particles.position(members[0]));
        else
          for (unsigned int j = 0; j < n; ++j)
            {
              trial_at(j);
              table.add_point(unl_point_weight(k, geom, family_volume, j),
                              g,
                              particles.position(members[j]));
            }
        return;
      }

    Assert(formulation.method == Method::ppg1 ||
             formulation.method == Method::ppg2,
           ExcInternalError());
    table.reinit(n, false);
    table.trial.reserve((n - 1) * n);
    const double share = particles.family_share(k);
    for (unsigned int j = 1; j < n; ++j)
      {
        trial_at(j);
        table.add_point(share * geom.volumes[j],
                        g,
                        particles.position(members[j]));
        const Tensor<1, dim> t = ppg_test_vector(k, j);
        table.add_test_vector(formulation.method == Method::ppg1 ? 0 : j, t);
        table.add_test_vector(formulation.method == Method::ppg1 ? j : 0, -t);
      }
  }



  template <int dim>
  void
  FamilyElements<dim>::use_particle_volume_weights()
  {
    Assert(formulation.method == FormulationCode::Method::pbg,
           ExcInternalError());
    // c(k) = V^k / V^{H^k} with the member (full body) volumes
    const unsigned int  n = particles.n_particles();
    std::vector<double> c(n, 0.);
    for (unsigned int k = 0; k < n; ++k)
      {
        double family_volume = 0;
        for (const unsigned int j : families.members(k))
          family_volume += particles.member_volume(j);
        c[k] = particles.member_volume(k) / family_volume;
      }
    // s(o) = sum of c over o's family (o itself first): the families that
    // hold o are its members' (an image's c is its original's)
    particle_weight_factors.assign(n, 0.);
    for (unsigned int o = 0; o < n; ++o)
      {
        double s = 0;
        for (const unsigned int j : families.members(o))
          s += c[particles.original(j)];
        particle_weight_factors[o] = 1. / s;
      }
  }



  template <int dim>
  double
  FamilyElements<dim>::unl_point_weight(
    const unsigned int                         k,
    const ShapeFunctions::FamilyGeometry<dim> &geometry,
    const double                               family_volume,
    const unsigned int                         q) const
  {
    const double w = particles.family_share(k) * geometry.volumes[0] *
                     geometry.volumes[q] / family_volume;
    if (particle_weight_factors.empty())
      return w;
    return w *
           particle_weight_factors[particles.original(families.members(k)[q])];
  }



  template <int dim>
  Tensor<1, dim>
  FamilyElements<dim>::ppg_test_vector(const unsigned int k,
                                       const unsigned int j) const
  {
    if (formulation.method == FormulationCode::Method::ppg2)
      return master_test[k][j];
    // PPG1: g^{jjk}, family j's master gradient for node k; for a mirror
    // image j of particle o across the planes M, the reflection of
    // family o's gradient for the image of k across M
    const auto [member, index] = member_family_index(k, j);
    Tensor<1, dim>     g       = master_test[member][index];
    const unsigned int image   = families.members(k)[j];
    for (unsigned int c = 0; c < dim; ++c)
      g[c] *= particles.mirror_sign(image, c);
    return g;
  }



  template <int dim>
  std::pair<unsigned int, unsigned int>
  FamilyElements<dim>::member_family_index(const unsigned int k,
                                           const unsigned int j) const
  {
    const unsigned int image  = families.members(k)[j];
    const unsigned int member = particles.original(image);
    const unsigned int master =
      particles.mirror_image(k, particles.mirror_mask(image));
    const auto family_j = families.members(member);
    const auto found =
      std::lower_bound(family_j.begin() + 1, family_j.end(), master);
    Assert(found != family_j.end() && *found == master,
           ExcMessage("The families are not pairwise."));
    return {member, static_cast<unsigned int>(found - family_j.begin())};
  }



  template <int dim>
  void
  FamilyElements<dim>::correct(const unsigned int    k,
                               QuadratureTable<dim> &table) const
  {
    Assert(!alpha.empty(), ExcMessage("Call set_correction_factors() first."));
    const unsigned int n = families.members(k).size();
    if (formulation.method != FormulationCode::Method::pbg)
      {
        // the test vectors of point j - 1 are (t, -t), see build()
        AssertDimension(table.test_vectors.size(), 2 * (n - 1));
        for (unsigned int j = 1; j < n; ++j)
          {
            const Tensor<1, dim> t              = ppg_test_vector(k, j);
            table.test_vectors[2 * (j - 1)]     = t;
            table.test_vectors[2 * (j - 1) + 1] = -t;
          }
        return;
      }
    if (formulation.points == FormulationCode::Points::u1)
      {
        AssertDimension(table.trial.size(), n);
        std::copy(master[k].begin(), master[k].end(), table.trial.begin());
        return;
      }
    AssertDimension(table.trial.size(), n * n);
    const ShapeFunctions::FamilyGeometry<dim> geom = geometry(k);
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int a = 0; a < n; ++a)
        table.trial[j * n + a] += correction(k, geom, j, a);
  }



  template <int dim>
  void
  FamilyElements<dim>::build(const std::vector<unsigned int>   &ks,
                             std::vector<QuadratureTable<dim>> &tables) const
  {
    tables.resize(ks.size());
    parallel_for_each_index(ks.size(), [&](const unsigned int f) {
      build(ks[f], tables[f]);
    });
  }



  template <int dim>
  void
  FamilyElements<dim>::correct(const std::vector<unsigned int>   &ks,
                               std::vector<QuadratureTable<dim>> &tables) const
  {
    AssertDimension(tables.size(), ks.size());
    parallel_for_each_index(ks.size(), [&](const unsigned int f) {
      correct(ks[f], tables[f]);
    });
  }



  template class FamilyElements<2>;
  template class FamilyElements<3>;
} // namespace pg
