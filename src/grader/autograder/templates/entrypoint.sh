#!/usr/bin/env bash
# PrairieLearn runs this for every submission: /grade/student in,
# /grade/results/results.json out. The grader always writes the results file (score 0 with
# the reason when the submission cannot be graded); this script writes one only when the
# grader itself could not start.
# PBRLAB_GRADE_ROOT replaces /grade and PBRLAB_SOURCE /pbrlab (the tests run it in a folder).
set -uo pipefail
root="${PBRLAB_GRADE_ROOT:-/grade}"
source_dir="${PBRLAB_SOURCE:-/pbrlab}"
results="$root/results/results.json"
mkdir -p "$root/results"
"$source_dir/target/release/pbrlab" autograder run --service prairielearn \
    --config "$source_dir/pbrlab-autograder.json" \
    --submission "$root/student" \
    --metadata "$root/data/data.json" \
    --results "$results"
status=$?
if [ ! -s "$results" ]; then
    printf '{"gradable": true, "score": 0, "message": "Not graded: the grader did not start (exit status %s)."}\n' \
        "$status" > "$results.tmp" && mv "$results.tmp" "$results"
fi
