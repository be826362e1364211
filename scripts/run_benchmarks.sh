#!/usr/bin/env bash
# Benchmarks the terrain batch run (200 s, dt 5 ms: 40,000 RK4 steps; 2,001 CSV rows):
#  1. bench_terrain (Google Benchmark): the sphere_sim command in-process, and the run without CSV;
#     bench_freebot: FreeBOT IK over 10,000 random reachable targets of a 3-joint chain;
#     bench_rotor: the two-rotor sphere's n-step planner (k 0..5 x n 1..5; target < 50 ms each);
#  2. the CPU time (user + sys) of whole `sphere_sim terrain` processes, one 200 s circle run per
#     robot type and tracking law, run from the install space without --config, against a 10 ms
#     target (issue 13: with --law smooth).
# usage: scripts/run_benchmarks.sh [REPEATS]    (processes per robot type, default 20)
# SR_BIN_DIR=DIR uses sphere_sim, bench_terrain and bench_rotor from DIR instead of building the
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
for program in sphere_sim bench_terrain bench_freebot bench_rotor; do
  [ -x "$bin/$program" ] || { sr_log "no $bin/$program (is libbenchmark-dev installed?)"; exit 1; }
done

sr_step "Google Benchmark: bench_terrain" "$bin/bench_terrain"
sr_step "Google Benchmark: bench_freebot (IK, 10,000 targets per case)" "$bin/bench_freebot"
sr_step "Google Benchmark: bench_rotor" "$bin/bench_rotor"

sr_log "CPU time of whole sphere_sim processes ($repeats per case)"
python3 - "$bin/sphere_sim" "$repeats" <<'EOF'
import os, statistics, subprocess, sys, tempfile

sim, repeats = sys.argv[1], int(sys.argv[2])
target_ms = 10.0
out = os.path.join(tempfile.mkdtemp(prefix='sphere_sim_bench.'), 'run.csv')
print('%-40s %12s %10s %10s %7s' % ('case', 'CPU ms/proc', 'min ms', 'target ms', 'ratio'))
for robot, law in [(r, l) for l in ('smooth', 'paper') for r in ('3R', '2R', 'RT', 'RS')]:
    args = [sim, 'terrain', '--robot', robot, '--path', 'circle', '--law', law, '--duration', '200',
            '--out', out]
    cpu_ms = []
    for _ in range(repeats):
        child = subprocess.Popen(args, stdout=subprocess.DEVNULL)
        _, status, usage = os.wait4(child.pid, 0)  # this child's own user + sys time
        if os.waitstatus_to_exitcode(status) != 0:
            sys.exit('%s failed with status %d' % (' '.join(args), os.waitstatus_to_exitcode(status)))
        cpu_ms.append(1000.0 * (usage.ru_utime + usage.ru_stime))
    median = statistics.median(cpu_ms)
    print('%-40s %12.1f %10.1f %10.0f %7.2f' % ('terrain %s circle 200 s, %s (median)' % (robot, law),
                                                median, min(cpu_ms), target_ms, median / target_ms))
os.remove(out)
os.rmdir(os.path.dirname(out))
EOF
