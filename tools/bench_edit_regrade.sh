#!/usr/bin/env bash
# Edit → regraded: the student's loop, timed (a bench script, not a test).
#
# For one closed-form task (smith_g1) and one integrator task (path_trace), puts a complete
# implementation in the exercise file (the reference's, when solutions/ is there, so the
# grade runs every check), appends a comment line to it (a real edit: the crate must be
# rebuilt), then times `cargo run --release -- grade TASK`, rebuild included, as a student
# runs it. Each is measured ROUNDS times; the exercise file is restored afterwards. Run from anywhere in the
# repository, after one `cargo build --release` (the clean build is not what this measures):
#
#   tools/bench_edit_regrade.sh [ROUNDS]
#
# Prints one line per run and the median per task, in seconds of wall time.
set -euo pipefail
cd "$(dirname "$0")/.."
rounds="${1:-3}"
cargo build --release --quiet

for task in smith_g1 path_trace; do
    file="exercises/$task.rs"
    backup="$(mktemp)"
    cp "$file" "$backup"
    trap 'cp "$backup" "$file"' EXIT
    implementation="$backup"
    if [ -f "solutions/$task.rs" ]; then implementation="solutions/$task.rs"; fi
    times=()
    for round in $(seq "$rounds"); do
        cp "$implementation" "$file"
        echo "// bench edit $round $(date +%s%N)" >>"$file"
        start=$(date +%s.%N)
        cargo run --release --quiet -- grade "$task" >/dev/null || true
        end=$(date +%s.%N)
        t=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')
        times+=("$t")
        echo "$task round $round: ${t} s"
    done
    median=$(printf '%s\n' "${times[@]}" | sort -n | sed -n "$(((rounds + 1) / 2))p")
    echo "$task: median ${median} s over $rounds edits (edit -> rebuilt -> graded)"
    cp "$backup" "$file"
    trap - EXIT
done
