#!/usr/bin/env bash
# Benchmarks the terrain batch run (200 s, dt 5 ms: 40,000 RK4 steps; 2,001 CSV rows):
#  1. bench_terrain (Google Benchmark): the sphere_sim command in-process, the run without CSV, and
#     a lower bound for the run (BM_TerrainStageFloor: the 3R smooth loop as straight-line code);
#     bench_freebot: FreeBOT IK over 10,000 random reachable targets of a 3-joint chain;
#     bench_rotor: the two-rotor sphere's n-step planner (k 0..5 x n 1..5; target < 50 ms each);
#  2. the CPU time (user + sys) of whole `sphere_sim` processes run from the install space without
#     --config, each against its target (issue 13): one 200 s terrain circle run per robot type
#     and tracking law (10 ms, with --law smooth), the floor's (bench_terrain_floor: the 3R smooth
#     run and its CSV as straight-line code, nothing read or checked), its fixed costs alone
#     (start-up: --help; start-up and configuration: --duration 0), the rotor planner's slowest
#     problems (50 ms) and the Norma paper run (40 ms).
# usage: scripts/run_benchmarks.sh [REPEATS]    (processes per robot type, default 20)
# SR_BIN_DIR=DIR uses the programs (sphere_sim, the bench_* ones) from DIR instead of building the
# workspace.
set -euo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/env.sh"
cd "$SR_ROOT"
repeats=${1:-20}

if [ -n "${SR_BIN_DIR:-}" ]; then
  bin=$SR_BIN_DIR
else
  sr_step "build (colcon, Release; incremental)" sr_build
  bin=install/spherical_robots/lib/spherical_robots
fi
for program in sphere_sim bench_terrain bench_terrain_floor bench_freebot bench_rotor; do
  [ -x "$bin/$program" ] || { sr_log "no $bin/$program (is libbenchmark-dev installed?)"; exit 1; }
done

sr_step "Google Benchmark: bench_terrain" "$bin/bench_terrain"
sr_step "Google Benchmark: bench_freebot (IK, 10,000 targets per case)" "$bin/bench_freebot"
sr_step "Google Benchmark: bench_rotor" "$bin/bench_rotor"

sr_log "CPU time of whole sphere_sim processes ($repeats per case)"
python3 - "$bin/sphere_sim" "$bin/bench_terrain_floor" "$repeats" <<'EOF'
import os, statistics, subprocess, sys, tempfile

sim, floor, repeats = sys.argv[1], sys.argv[2], int(sys.argv[3])
out = os.path.join(tempfile.mkdtemp(prefix='sphere_sim_bench.'), 'run.out')
cases = [('terrain %s circle 200 s, %s' % (robot, law),
          ['terrain', '--robot', robot, '--path', 'circle', '--law', law, '--duration', '200'],
          10.0 if law == 'smooth' else None)
         for law in ('smooth', 'paper') for robot in ('3R', '2R', 'RT', 'RS')]
cases += [('floor: bench_terrain_floor (3R smooth)', [floor], 10.0)]
cases += [('start-up (sphere_sim --help)', ['--help'], None),
          ('start-up + configuration (terrain, 0 s)',
           ['terrain', '--robot', '3R', '--path', 'circle', '--law', 'smooth', '--duration', '0'],
           None)]
cases += [('rotor-plan k %g, n %d' % (k, n),
           ['rotor-plan', '--k', str(k), '--steps', str(n), '--target', '0.4,0.7,0.6'], 50.0)
          for k, n in ((3.75, 5), (5, 3), (5, 4), (5, 5))]
cases += [('norma paper run, 1300 s', ['norma'], 40.0)]
print('%-42s %12s %10s %10s %7s' % ('case', 'CPU ms/proc', 'min ms', 'target ms', 'ratio'))
for label, case_args, target_ms in cases:
    if case_args == [floor]:
        args = [floor, out]
    else:
        args = [sim] + case_args + ([] if case_args == ['--help'] else ['--out', out])
    cpu_ms = []
    for _ in range(repeats):
        child = subprocess.Popen(args, stdout=subprocess.DEVNULL)
        _, status, usage = os.wait4(child.pid, 0)  # this child's own user + sys time
        if os.waitstatus_to_exitcode(status) != 0:
            sys.exit('%s failed with status %d' % (' '.join(args), os.waitstatus_to_exitcode(status)))
        cpu_ms.append(1000.0 * (usage.ru_utime + usage.ru_stime))
    median = statistics.median(cpu_ms)
    target = ('%10.0f %7.2f' % (target_ms, median / target_ms)) if target_ms else '%10s %7s' % ('', '')
    print('%-42s %12.1f %10.1f %s' % (label, median, min(cpu_ms), target))
os.remove(out)
os.rmdir(os.path.dirname(out))
EOF
