# Helper, not a benchmark: it has no page of its own and is not run by
# itself (doc/benchmarks/README.md, "Helpers"); the benchmark is
# torsion_prism.sh, its page torsion_prism.md.
# The torsion prism of B-10 (Table 7.4), sourced by torsion_prism.sh and
# mixed_cost.sh: a square prism 1 x 1 x 5 mm on N x N x 5N cells,
# isochoric-volumetric neo-Hooke with K = 500 MPa and mu = 161.148 MPa
# (the source's 5e8 and 1.61148e8 N/m^2), clamped at the bottom (z = 0,
# id 4) and turned about its axis at the top (z = 5, id 5), where x and y
# follow the rotation and z is held. Equal load steps without step cuts,
# at most 30 Newton iterations each, direct solver, no VTU.
#
# torsion_prm N FORMULATION HORIZON_FACTOR DEGREES LOAD_STEPS PREDICTOR OUTPUT_DIRECTORY
#   prints the parameter file. A caller adds entries by appending
#   subsections to it (ParameterHandler reads a subsection that is opened
#   twice as one), e.g. 'Points' in subsection Output.
torsion_prm() {
  radians=$(awk "BEGIN { printf \"%.15g\", $4 * atan2(0, -1) / 180 }")
  cat <<END
set Dimension = 3
subsection Geometry
  set Mesh          = hyper rectangle
  set Lower corner  = 0, 0, 0
  set Upper corner  = 1, 1, 5
  set Subdivisions  = $1, $1, $((5 * $1))
end
subsection Discretization
  set Formulation    = $2
  set Horizon factor = $3
end
subsection Material
  set Model         = isochoric-volumetric neo-Hooke
  set Bulk modulus  = 500
  set Shear modulus = 161.148
end
subsection Boundary conditions
  set Dirichlet = 4: xyz, 5: xyz
  subsection Prescribed displacement
    set Function constants  = a=$radians
    set Function expression = 0.5 + (x - 0.5)*cos(a*t*z/5) - (y - 0.5)*sin(a*t*z/5) - x; 0.5 + (x - 0.5)*sin(a*t*z/5) + (y - 0.5)*cos(a*t*z/5) - y; 0
  end
end
subsection Loading
  set Load steps        = $5
  set Maximum step cuts = 0
  set Predictor         = $6
end
subsection Newton
  set Maximum iterations = 30
end
subsection Linear solver
  set Type = direct
end
subsection Output
  set Directory = $7
  set VTU       = false
end
END
}
