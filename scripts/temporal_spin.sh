#!/bin/sh
# LTL verdicts against SPIN on N random models x 5 formulas (issue 16 asks for >= 200 pairs):
#   sh scripts/temporal_spin.sh [MODELS] [ENGINE]   (default 40 models = 200 pairs, engine auto)
# ENGINE ic3 compares the SAT liveness engines (liveness-to-safety + k-liveness) with SPIN.
# Needs spin and gcc. The suite runs the same test on 8 models (crates/cli/tests/temporal_spin.rs).
set -eu
cd "$(dirname "$0")/.."
STATECHECK_SPIN_MODELS=${1:-40} STATECHECK_SPIN_ENGINE=${2:-auto} \
  cargo test --release -p statecheck-cli --test temporal_spin -- --nocapture
