#!/bin/sh
# bench/glsl_budget.sh [ARGS] - prints the GLSL compile (+ link + first draw) and run-time
# table of bench/glsl_budget.c with the Mesa shader cache off. ARGS: --check F (exit 1 past F
# times a budget), --no-run (compile table only), --one-include (shlight.glsl), GLSL_DIR.
set -e
cd "$(dirname "$0")/.."
make -s build/bench/glsl_budget
MESA_SHADER_CACHE_DISABLE=true exec build/bench/glsl_budget "$@"
