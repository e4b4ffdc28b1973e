#!/bin/sh
# Wall times of two pg_solve builds on the same cases, run interleaved (A, B,
# A, B, ...) so that a change of the machine's load hits both alike; each
# figure is the median of the repeats. Used for issue 12 (the core rebuilt:
# doc/benchmarks/core_before_after.md) and meant for every change that
# should not cost time.
#
# Cases (2-D, one MPI rank), the two of issue 12's "Done when":
#  * explicit: prm/ganzenmueller_patch.prm as it is (484 vertices, 32 time
#    units of leapfrog, 1,500 to 3,200 steps: shorter runs scatter by
#    20 %), total wall time per step and vertex in microseconds, for FEM,
#    PBG U1, VCBCPBG Unl and CPD (C1 as in explicit_step_cost.sh);
#  * study: pg_study on prm/plate_with_hole_study.prm as it is (FEM, PG
#    everywhere and four coupled models, regular and distorted, refinement
#    2 to 6, direct solver): the wall time of the whole study in seconds.
#
# Usage (from the repository root; both build trees Release, with
# applications/pg_solve/pg_solve and applications/pg_study/pg_study):
#   sh doc/benchmarks/before_after.sh OLD_BUILD NEW_BUILD [repeats [study_repeats]] > table.md
# (repeats: default 3; study_repeats: default repeats, 0 leaves the study
# out; one study run takes about 3.5 minutes here)
set -e
OLD=$1/applications/pg_solve/pg_solve
NEW=$2/applications/pg_solve/pg_solve
OLD_STUDY=$1/applications/pg_study/pg_study
NEW_STUDY=$2/applications/pg_study/pg_study
REPEATS=${3:-3}
STUDY_REPEATS=${4:-$REPEATS}
[ -x "$OLD" ] && [ -x "$NEW" ] && [ -x "$OLD_STUDY" ] && [ -x "$NEW_STUDY" ] || {
  echo "usage: $0 OLD_BUILD NEW_BUILD [repeats]" >&2
  exit 1
}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

# write_case NAME: the parameter file $WORK/NAME.prm (from $BASE and $EXTRA)
write_case() {
  cat "$BASE" - > "$WORK/$1.prm" <<END
$EXTRA
subsection Output
  set Directory = $WORK/out_$1
  set VTU       = false
end
END
}

# field FILE NAME: the seconds of line NAME of a timing.txt
field() {
  awk -v n="$2" '$1 == n { print $2 }' "$1"
}

median() {
  sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : 0.5 * (v[NR / 2] + v[NR / 2 + 1]) }'
}

# run CASE: REPEATS interleaved runs of both binaries; per-run figures in
# $WORK/CASE.old and $WORK/CASE.new ("total assembly vc solve steps")
run() {
  : > "$WORK/$1.old"
  : > "$WORK/$1.new"
  for r in $(seq "$REPEATS"); do
    for which in old new; do
      [ "$which" = old ] && bin=$OLD || bin=$NEW
      rm -rf "$WORK/out_$1"
      "$bin" "$WORK/$1.prm" > "$WORK/$1.$which.log" 2>&1
      t="$WORK/out_$1/timing.txt"
      steps=$(grep -o '"load_steps": [0-9]*' "$WORK/out_$1/summary.json" | grep -o '[0-9]*$')
      echo "$(field "$t" total) $(field "$t" assembly) $(field "$t" vc) $(field "$t" solve) $steps" >> "$WORK/$1.$which"
    done
  done
}

# column CASE WHICH N: the median of column N
column() {
  awk -v c="$3" '{ print $c }' "$WORK/$1.$2" | median
}

echo "| case | old | new | new/old |"
echo "|---|---|---|---|"

BASE=prm/ganzenmueller_patch.prm
for code in "FEM" "PBG U1" "VCBCPBG Unl" "CPD"; do
  name=explicit_$(echo "$code" | tr ' ' '_')
  EXTRA="subsection Discretization
  set Formulation = $code
end
subsection Time
  set Output interval = 0
end
subsection CPD
  set C1 = 3267
end"
  write_case "$name"
  run "$name"
  steps=$(column "$name" old 5)
  o=$(column "$name" old 1 | awk -v s="$steps" '{ printf "%.2f", 1e6 * $1 / (s * 484) }')
  n=$(column "$name" new 1 | awk -v s="$steps" '{ printf "%.2f", 1e6 * $1 / (s * 484) }')
  echo "| explicit $code, us/(step vertex) | $o | $n | $(echo "$n $o" | awk '{ printf "%.3f", $1 / $2 }') |"
done

# The study: the file as it is, with its problem file found from $WORK.
if [ "$STUDY_REPEATS" -gt 0 ]; then
sed -e "s|= plate_with_hole_coupled.prm|= $(pwd)/prm/plate_with_hole_coupled.prm|" \
    -e "s|set Directory *= study_plate_with_hole|set Directory = $WORK/study|" \
    prm/plate_with_hole_study.prm > "$WORK/study.prm"
: > "$WORK/study.old"
: > "$WORK/study.new"
for r in $(seq "$STUDY_REPEATS"); do
  for which in old new; do
    [ "$which" = old ] && bin=$OLD_STUDY || bin=$NEW_STUDY
    rm -rf "$WORK/study"
    start=$(date +%s.%N)
    "$bin" "$WORK/study.prm" > "$WORK/study.$which.log" 2>&1
    end=$(date +%s.%N)
    echo "$start $end" | awk '{ print $2 - $1 }' >> "$WORK/study.$which"
  done
done
o=$(median < "$WORK/study.old")
n=$(median < "$WORK/study.new")
echo "| plate-with-hole study (levels 2-6), wall (s) | $(printf %.1f "$o") | $(printf %.1f "$n") | $(echo "$n $o" | awk '{ printf "%.3f", $1 / $2 }') |"
fi
echo
echo "Medians of $REPEATS interleaved runs each (the study: $STUDY_REPEATS); $(nproc) cores; $(date -u +%Y-%m-%d)."
