#!/usr/bin/env bash
# Regenerates every figure and table of docs/results.md from the built package (sphere_sim, and
# with --with-rviz the launched stacks): the one command docs/results.md names.
#
#   scripts/make_results.sh [--with-rviz] [--out-dir DIR]
#
# Writes into docs/ (the tracked figures; `git diff` shows what moved) unless --out-dir DIR is
# given: then DIR/figures gets the same files (the tables are printed, not written), to compare
# with docs/ without touching it.
#
# Batch part (~2 min): terrain_results.py (16 terrain runs), rotor_figures.py (Figs 9, 10),
# freebot_results.py (Table II targets), the two 1300 s Norma runs and plot_norma_run.py.
# --with-rviz (~4.5 min more): rviz_figures.sh records each stack and screenshots its bag.
set -euo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/env.sh"
sim=$SR_ROOT/install/spherical_robots/lib/spherical_robots/sphere_sim
[ -x "$sim" ] || { sr_log "no $sim: build first (scripts/run_tests.sh or scripts/run_demo.sh)"; exit 1; }
docs=$SR_ROOT/docs
with_rviz=false
while [ $# -gt 0 ]; do
  case $1 in
    --with-rviz) with_rviz=true; shift ;;
    --out-dir)
      [ $# -ge 2 ] || { sr_log "--out-dir needs a directory"; exit 2; }
      docs=$(realpath -m "$2"); shift 2 ;;
    *) sr_log "unknown argument '$1' (usage: scripts/make_results.sh [--with-rviz] [--out-dir DIR])"; exit 2 ;;
  esac
done
mkdir -p "$docs/figures"
work=$(mktemp -d /tmp/make_results.XXXXXX)
trap 'rm -rf "$work"' EXIT

sr_step "terrain: 16 runs, table and figures" python3 "$SR_ROOT/scripts/terrain_results.py" "$sim" --out-dir "$docs"
sr_step "rotor: Figs 9 and 10" python3 "$SR_ROOT/scripts/rotor_figures.py" "$sim" "$docs/figures"
sr_step "FreeBOT: Table II targets" python3 "$SR_ROOT/scripts/freebot_results.py" "$sim" --out-dir "$docs"
norma() {
  local controller=$1
  "$sim" norma --controller "$controller" --out "$work/norma_$controller.csv"
  python3 "$SR_ROOT/scripts/plot_norma_run.py" "$work/norma_$controller.csv" \
    "$docs/figures/norma_$controller.png" "sphere_sim norma --controller $controller (eq 52, text Lagrangian)"
}
sr_step "Norma: paper controller, 1300 s" norma paper
sr_step "Norma: tracking controller, 1300 s" norma tracking
if $with_rviz; then
  sr_step "rviz screenshots of recorded stack runs" "$SR_ROOT/scripts/rviz_figures.sh" "$docs/figures"
fi
sr_log "done: $docs/figures and the tables printed above (copy changed numbers into docs/results.md)"
