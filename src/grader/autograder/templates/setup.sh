#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image: it installs the
# Rust toolchain and builds the framework, the reference, a worker and the reference's
# one-task libraries the workers load, so that grading a submission later rebuilds only the
# student's crate, offline.
# PBRLAB_SKIP_TOOLCHAIN=1 skips the system packages and rustup (a machine that has them).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
source_dir="${PBRLAB_SOURCE:-$here/pbrlab}"
if [ "${PBRLAB_SKIP_TOOLCHAIN:-0}" != 1 ]; then
    apt-get update
    apt-get install -y --no-install-recommends build-essential ca-certificates curl git
    curl --proto '=https' --tlsv1.2 -sSf https://sh.rustup.rs |
        sh -s -- -y --profile minimal --default-toolchain @TOOLCHAIN@
fi
# shellcheck disable=SC1091
[ -f "$HOME/.cargo/env" ] && source "$HOME/.cargo/env"
cd "$source_dir"
cargo build --release --locked --bins
@REFERENCE_LIBRARIES@
