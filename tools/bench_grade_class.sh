#!/usr/bin/env bash
# A class regrade, timed (a bench script, not a test): generates N submissions (default 50)
# from the reference and the stubs — complete, partial, empty, one file that does not
# compile, one task wrong — grades them with `pbrlab grade-class`, and prints the seconds per
# submission and how many were not graded (infrastructure failures: should be 0). A second
# run over the same folder shows the resume (nothing left to grade).
#
#   tools/bench_grade_class.sh [N]
set -euo pipefail
cd "$(dirname "$0")/.."
n="${1:-50}"
cargo build --release --quiet --bins
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
tasks=(reflect refract_stack fresnel_schlick cosine_sample smith_g1 beckmann_ndf cook_torrance
    ndf_sample aniso_ndf phong brdf_check kajiya_kay path_trace mis delta_tracking)
for i in $(seq -w 1 "$n"); do
    dir="$work/submissions/student$i"
    mkdir -p "$dir/exercises"
    case $((10#$i % 5)) in
        0) ;; # an empty submission: every task its stub
        1) cp solutions/*.rs "$dir/exercises/" && rm -f "$dir/exercises/lib.rs" ;;
        2) for t in "${tasks[@]:0:$((10#$i % 15 + 1))}"; do cp "solutions/$t.rs" "$dir/exercises/"; done ;;
        3) cp solutions/*.rs "$dir/exercises/" && rm -f "$dir/exercises/lib.rs"
           t="${tasks[$((10#$i % 15))]}"
           printf '\npub fn broken( {\n' >>"$dir/exercises/$t.rs" ;;
        4) cp solutions/*.rs "$dir/exercises/" && rm -f "$dir/exercises/lib.rs"
           sed -i 's/2.0 \* c \/ (c + root)/2.0 * c \/ (c + root + 0.01)/' "$dir/exercises/smith_g1.rs" ;;
    esac
done
start=$(date +%s.%N)
target/release/pbrlab grade-class "$work/submissions" --out "$work/out"
end=$(date +%s.%N)
echo "graded $n submissions in $(echo "$end - $start" | bc) s: $(echo "($end - $start) / $n" | bc -l | cut -c1-5) s per submission"
echo "not graded: $(grep -l '"status": "not graded"' "$work"/out/students/*.json | wc -l)"
target/release/pbrlab grade-class "$work/submissions" --out "$work/out"
head -3 "$work/out/class.csv" | cut -c1-160
sed -n '1,12p' "$work/out/summary.md"
