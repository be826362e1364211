#!/usr/bin/env python3
"""Recovery times of every node of the terrain and Norma loops (docs/conventions.md, "When a node
dies"): for each, one run of test/stack_supervision_check.py (its stack under run_stack.py with
respawn:=true on a master of its own, two busy loops beside it, kill -9 of the node mid-run), and
a table of what it measured: the wall time from the kill to the node's return (a new process
registered under its name) and to its first new output, the simulated time without its output
(the largest gap between the stamps of its messages around the kill), and |e_t| over the last
20 s against the normal run's (the batch run of the same scenario).

    test/recovery_table.py                  # all six, about 5 minutes on 2 cores
    test/recovery_table.py --only terrain   # the three of one stack

Not a rostest: the rostests stack_supervision_*_respawn.test check one node of each kind.
"""
import argparse
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.realpath(__file__))
CHECK = os.path.join(HERE, 'stack_supervision_check.py')
# stack, node, the check's options and launch arguments
RUNS = [
    ('terrain', 'pure_pursuit_controller', ['--at', '20', '--duration', '60', 'speedup:=10']),
    ('terrain', 'hardware_interface', ['--at', '20', '--duration', '60', 'speedup:=10']),
    ('terrain', 'terrain_plant', ['--at', '20', '--duration', '60', 'speedup:=10']),
    ('norma', 'norma_controller', ['--at', '10', '--duration', '40', 'controller:=tracking']),
    ('norma', 'hardware_interface', ['--at', '10', '--duration', '40', 'controller:=tracking']),
    ('norma', 'norma_plant', ['--at', '10', '--duration', '40', 'controller:=tracking']),
]
RECOVERY = re.compile(r'RECOVERY stack=(\S+) node=(\S+) back=(\S+) first_output=(\S+) '
                      r'sim_gap=(\S+) e_max=(\S+) e_normal=(\S+)')


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--only', choices=['terrain', 'norma'])
    args = parser.parse_args()
    rows = []
    for stack, node, options in RUNS:
        if args.only and stack != args.only:
            continue
        run = subprocess.run([sys.executable, CHECK, '--stack', stack, '--kill', node, '--respawn']
                             + options, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        found = RECOVERY.search(run.stdout)
        passed = run.returncode == 0 and 'RESULT: SUCCESS' in run.stdout
        if not found:
            rows.append('| %s | `%s` | no measurement (exit %d) |  |  |  | %s |'
                        % (stack, node, run.returncode, 'passed' if passed else 'FAILED'))
            sys.stderr.write(run.stdout[-3000:])
            continue
        _, _, back, first, gap, e_max, e_normal = found.groups()
        rows.append('| %s | `%s` | %s | %s | %s | %s (normal %s) | %s |'
                    % (stack, node, back, first, gap, e_max, e_normal,
                       'passed' if passed else 'FAILED'))
        print(rows[-1], flush=True)
    print('\n| stack | node killed | back [s wall] | first output [s wall] | simulated time '
          'without its output [s] | max \\|e_t\\| over the last 20 s [m] | checks |')
    print('|---|---|---|---|---|---|---|')
    print('\n'.join(rows))


if __name__ == '__main__':
    main()
