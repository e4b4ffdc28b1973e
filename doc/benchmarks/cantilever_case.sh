# Helper, not a benchmark: it has no page of its own and is not run by
# itself (doc/benchmarks/README.md, "Helpers").
# The cantilever of the solver benchmarks (amg_iterations.sh,
# amg_tuning.sh, amg_operator.sh, vc_solve.sh, scaling.sh), sourced by them:
# 4 x 1 x 1 (3-D) or 4 x 1 (2-D) on n x n/4 (x n/4) cells distorted by 0.25,
# clamped at x = 0, a dead downward traction of 1 on x = 4, neo-Hooke
# E = 1000, nu = 0.3, one load step, Krylov tolerance 1e-10, no VTU, the
# tip (4, 0.5, 0.5) as output point.
#
# cantilever_prm DIM N FORMULATION SOLVER OUTPUT_DIRECTORY
#   prints the parameter file. A caller adds entries by appending
#   subsections to it (ParameterHandler reads a subsection that is opened
#   twice as one), e.g. 'Horizon factor' in subsection Discretization.
cantilever_prm() {
  m=$(($2 / 4))
  echo "set Dimension = $1"
  echo "subsection Geometry"
  if [ "$1" = 3 ]; then
    printf '  set Lower corner = 0, 0, 0\n  set Upper corner = 4, 1, 1\n'
    printf '  set Subdivisions = %s, %s, %s\n' "$2" "$m" "$m"
    clamp=xyz
    traction="0; 0; -1*t"
    tip="4, 0.5, 0.5"
  else
    printf '  set Lower corner = 0, 0\n  set Upper corner = 4, 1\n'
    printf '  set Subdivisions = %s, %s\n' "$2" "$m"
    clamp=xy
    traction="0; -1*t"
    tip="4, 0.5"
  fi
  cat <<END
  set Distortion   = 0.25
end
subsection Discretization
  set Formulation = $3
end
subsection Material
  set Model           = neo-Hooke
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
end
subsection Boundary conditions
  set Dirichlet = 0: $clamp
  set Neumann   = 1
  subsection Traction
    set Function expression = $traction
  end
end
subsection Loading
  set Load steps = 1
end
subsection Linear solver
  set Type      = $4
  set Tolerance = 1e-10
end
subsection Output
  set Directory = $5
  set VTU       = false
  set Points    = tip: $tip
end
END
}

# summary_number SUMMARY_JSON KEY: the first number after "KEY": in it
summary_number() {
  grep -o "\"$2\": [0-9.e+-]*" "$1" | head -1 | awk '{ print $2 }'
}

# failure_reason LOG: the first line of the message with which pg_solve
# stopped (the line after deal.II's "Exception on processing:"), at most
# 160 characters, for the "failed:" cell of a table row
failure_reason() {
  grep -A1 -m1 'Exception on processing' "$1" | tail -1 | cut -c1-160
}
