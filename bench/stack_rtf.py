#!/usr/bin/env python3
"""Real-time factor of the launched stacks in lock-step, as separate processes and as nodelets
(issue 19's targets), with the wall time per step and the ratio to each target.

Each run is a roslaunch on a master of its own (a free port, its own ROS_HOME); the figure is the
plant's own "real-time factor" on /diagnostics (simulated time since the first step over wall time
since then), as reported last before the stack ended. No recorder or rviz runs beside it. Run it
after sourcing the built workspace (scripts/env.sh: sr_source_workspace):

    bench/stack_rtf.py [--repeats N] [--terrain-duration 200] [--norma-duration 30] [--low-latency]
                       [--loop-cpu auto|none|N]

With --low-latency the stacks run with low_latency:=true (the CPUs' wake-up latency held at 0 us;
as root; docs/lockstep.md, "Wake-up latency"); --loop-cpu none spreads the loop's nodes over the
CPUs as the kernel places them (the default, auto, puts them on one: "One CPU for the loop").

It prints, per stack and way of running, the best real-time factor of the repeats (all of them
in brackets), the wall time per plant step at that factor, the target and the ratio to it.
"""
import argparse
import os
import socket
import subprocess
import sys
import tempfile

# name, launch file, arguments, plant status (suffix of its /diagnostics name), step [s], targets
# (processes, nodelets) [x real time]. The terrain case is the default run with ideal actuators
# (hardware:=sim without actuator models); lock-step without a cap is the stacks' default.
CASES = [
    ('terrain 3R circle', 'terrain_stack.launch', ['robot:=3R', 'path:=circle'], ': terrain plant',
     0.01, (40.0, 150.0)),
    ('norma tracking', 'norma_stack.launch', ['controller:=tracking'], ': norma plant', 0.001,
     (2.0, 5.0)),
]


def free_port():
    with socket.socket() as s:
        s.bind(('localhost', 0))
        return s.getsockname()[1]


def listen(suffix):
    """Prints the real-time factor of every report of the status ending in `suffix`."""
    import rospy
    from diagnostic_msgs.msg import DiagnosticArray

    def on_diagnostics(msg):
        for status in msg.status:
            if status.name.endswith(suffix):
                for kv in status.values:
                    if kv.key == 'real-time factor':
                        print('rtf', kv.value, flush=True)

    rospy.init_node('stack_rtf_listener', anonymous=True, disable_signals=True)
    rospy.Subscriber('/diagnostics', DiagnosticArray, on_diagnostics, queue_size=10)
    rospy.spin()


def run(launch, args, suffix, duration, nodelet, workdir):
    """One stack run: the plant's last reported real-time factor."""
    port = free_port()
    env = dict(os.environ, ROS_MASTER_URI='http://localhost:%d' % port,
               ROS_HOME=tempfile.mkdtemp(dir=workdir))
    command = ['roslaunch', '-p', str(port), 'spherical_robots', launch, 'duration:=%g' % duration,
               'nodelet:=%s' % ('true' if nodelet else 'false')] + args
    log_path = os.path.join(env['ROS_HOME'], 'roslaunch.log')
    with open(log_path, 'w') as log:
        stack = subprocess.Popen(command, env=env, stdout=log, stderr=subprocess.STDOUT)
        # /clock remapped: the listener needs no time, and would be one more process to wake every
        # step.
        listener = subprocess.Popen([sys.executable, os.path.abspath(__file__), '--listen', suffix,
                                     '/clock:=stack_rtf_unused_clock'],
                                    env=env, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                                    text=True)
        stack.wait(timeout=120 + 10 * duration)
        listener.kill()
        reports = [line.split()[1] for line in listener.communicate()[0].splitlines()
                   if line.startswith('rtf ')]
    reports = [float(r) for r in reports if r not in ('nan', '-nan')]
    if stack.returncode != 0 or not reports:
        raise RuntimeError('%s: exit %d, %d reports (log %s)' % (' '.join(command), stack.returncode,
                                                                 len(reports), log_path))
    return reports[-1]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--listen', help=argparse.SUPPRESS)
    parser.add_argument('--repeats', type=int, default=1)
    parser.add_argument('--terrain-duration', type=float, default=200.0, help='[s] simulated')
    parser.add_argument('--norma-duration', type=float, default=30.0, help='[s] simulated')
    parser.add_argument('--low-latency', action='store_true',
                        help='low_latency:=true: the CPU wake-up latency held at 0 us (needs root)')
    parser.add_argument('--loop-cpu', default='auto',
                        help="loop_cpu:= (auto, none or a CPU number; default auto)")
    options, remappings = parser.parse_known_args()  # the listener's ROS remappings
    if remappings and not options.listen:
        parser.error('unknown arguments: %s' % ' '.join(remappings))
    if options.listen:
        listen(options.listen)
        return
    durations = {'terrain_stack.launch': options.terrain_duration,
                 'norma_stack.launch': options.norma_duration}
    workdir = tempfile.mkdtemp(prefix='stack_rtf.')
    print('%-18s %-9s %7s %18s %14s %7s %6s' % ('stack', 'as', 'sim [s]', 'real-time x (all)',
                                              'wall/step [us]', 'target', 'ratio'))
    for name, launch, args, suffix, step, targets in CASES:
        for nodelet, target in zip((False, True), targets):
            # The best of the repeats: the run the rest of the machine disturbed least.
            rtfs = [run(launch, args + ['loop_cpu:=' + options.loop_cpu]
                        + (['low_latency:=true'] if options.low_latency else []),
                        suffix, durations[launch], nodelet, workdir)
                    for _ in range(options.repeats)]
            best = max(rtfs)
            print('%-18s %-9s %7g %6.1f (%9s) %14.1f %7g %6.2f'
                  % (name, 'nodelets' if nodelet else 'processes', durations[launch], best,
                     ' '.join('%.1f' % r for r in rtfs), 1e6 * step / best, target, best / target),
                  flush=True)
    print('logs in', workdir)


if __name__ == '__main__':
    main()
