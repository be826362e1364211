#!/usr/bin/env python3
"""Runs rviz with its display config at another frame rate (launch/replay.launch's
rviz_frame_rate, as the rviz node's launch-prefix):

    rviz_frame_rate.py RATE rviz -d CONFIG.rviz [rviz arguments...]

rviz has no command-line option for the rate it draws at, only the config's "Frame Rate" (30 in
rviz/*.rviz). Under software OpenGL (Mesa's llvmpipe: Xvfb, a machine without a GPU) drawing
costs CPU at every frame; a lower rate leaves it to the rest. The config is copied with that one
value changed to a temporary file (removed when rviz ends), and rviz runs on the copy.
"""
import math
import os
import subprocess
import sys
import tempfile

import yaml


def usage(problem):
    sys.exit('rviz_frame_rate.py: %s\nusage: rviz_frame_rate.py RATE rviz -d CONFIG.rviz [ARGS...]'
             % problem)


def main(argv):
    if len(argv) < 3:
        usage('too few arguments')
    try:
        rate = float(argv[0])
    except ValueError:
        rate = float('nan')
    if not (math.isfinite(rate) and rate > 0.0):
        usage('RATE %r is not a number > 0 [frames/s]' % argv[0])
    command = argv[1:]
    if '-d' not in command[:-1]:
        usage('no -d CONFIG in %s' % ' '.join(command))
    where = command.index('-d') + 1
    with open(command[where]) as f:
        config = yaml.safe_load(f)
    config.setdefault('Visualization Manager', {}).setdefault('Global Options', {})[
        'Frame Rate'] = int(round(rate)) if rate >= 1.0 else rate
    with tempfile.NamedTemporaryFile('w', prefix='rviz_frame_rate.', suffix='.rviz',
                                     delete=False) as copy:
        yaml.safe_dump(config, copy, default_flow_style=False, sort_keys=False)
    command[where] = copy.name
    try:
        return subprocess.call(command)
    finally:
        os.remove(copy.name)


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
