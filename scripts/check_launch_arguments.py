#!/usr/bin/env python3
"""Checks a launch file's arguments against their domains before anything starts.

The launch files run it from a <param command="..."> tag, which roslaunch executes while it
reads the file, before it starts a master or any node:

    <param name="$(arg ns)/launch_arguments" command="$(find spherical_robots)/scripts/
        check_launch_arguments.py terrain_stack 'robot=$(arg robot)' 'path=$(arg path)' ..."/>

The first word names the launch file, as its path in launch/ without .launch (for the arguments
whose domain depends on the file); each further word is NAME=VALUE. A bad value prints, as the
first line on stderr,

    argument 'robot' = '4R': expected one of 3R, 2R, RT, RS

(a line per bad argument) and exits 1, and roslaunch stops with "Cannot load command
parameter". Otherwise it prints the arguments as YAML, the parameter's value: what the stack was
launched with. An argument without a domain here is a mistake in a launch file (exit 2).

DOMAINS below is the one place that says what each argument may be; the launch files' doc=
texts describe the arguments for `roslaunch --ros-args`.
"""
import math
import os
import re
import sys

import yaml

NAME = r'[A-Za-z][A-Za-z0-9_]*'
RELATIVE_NAME = re.compile(r'^%s(/%s)*$' % (NAME, NAME))
ABSOLUTE_NAME = re.compile(r'^(/%s)+$' % NAME)


class Domain:
    """What an argument may be: check() returns None or what was expected."""

    def check(self, value, arguments):
        raise NotImplementedError


class Choice(Domain):
    def __init__(self, *choices):
        self.choices = choices

    def check(self, value, arguments):
        if value not in self.choices:
            return 'expected one of ' + ', '.join(self.choices)
        return None


class Boolean(Domain):
    # What roslaunch's if= and unless= accept.
    def check(self, value, arguments):
        if value.lower() not in ('true', 'false', '1', '0'):
            return 'expected true or false'
        return None


def parse_number(value):
    try:
        number = float(value)
    except ValueError:
        return None
    return number if math.isfinite(number) else None


class Number(Domain):
    """A finite number, at least (or above) a bound; whole=True: an integer."""

    def __init__(self, minimum=None, above=None, whole=False, unit=''):
        self.minimum, self.above, self.whole, self.unit = minimum, above, whole, unit

    def describe(self):
        kind = 'a whole number' if self.whole else 'a number'
        if self.above is not None:
            kind += ' > %g' % self.above
        elif self.minimum is not None:
            kind += ' >= %g' % self.minimum
        return kind + (' [%s]' % self.unit if self.unit else '')

    def check(self, value, arguments):
        number = parse_number(value)
        if (number is None or (self.whole and not re.match(r'^-?[0-9]+$', value))
                or (self.minimum is not None and number < self.minimum)
                or (self.above is not None and number <= self.above)):
            return 'expected ' + self.describe()
        return None


class Speedup(Domain):
    """In lock-step a cap (0: none); with clock:=free the pace, which 0 would stop."""

    CAP = Number(minimum=0, unit='x real time')
    PACE = Number(above=0, unit='x real time')

    def check(self, value, arguments):
        if arguments.get('clock') == 'free':
            expected = self.PACE.check(value, arguments)
            return expected and expected + ' with clock:=free'
        return self.CAP.check(value, arguments)


class NumberList(Domain):
    """Comma-separated (or a YAML list of) finite numbers; count: how many, or a function of the
    arguments."""

    def __init__(self, count=None, above=None, describe='', yaml_list=False):
        self.count, self.above, self.text, self.yaml_list = count, above, describe, yaml_list

    def check(self, value, arguments):
        if self.yaml_list:
            try:
                items = yaml.safe_load(value)
            except yaml.YAMLError:
                items = None
            items = [str(i) for i in items] if isinstance(items, list) else None
        else:
            items = value.split(',')
        count = self.count(arguments) if callable(self.count) else self.count
        numbers = [parse_number(i) for i in items] if items is not None else [None]
        if (None in numbers or (count is not None and len(numbers) != count)
                or (self.above is not None and min(numbers) <= self.above)):
            return 'expected ' + self.text
        return None


class LoopCpu(Domain):
    """auto, none, or a CPU this process may run on (os.sched_getaffinity)."""

    def check(self, value, arguments):
        cpus = sorted(os.sched_getaffinity(0))
        if value in ('auto', 'none') or (re.match(r'^[0-9]+$', value) and int(value) in cpus):
            return None
        return 'expected auto, none or one of the CPUs %s' % ', '.join(map(str, cpus))


class Optional(Domain):
    """'none', or what the inner domain allows."""

    def __init__(self, inner):
        self.inner = inner

    def check(self, value, arguments):
        if value == 'none':
            return None
        expected = self.inner.check(value, arguments)
        return expected and expected.replace('expected ', 'expected none or ', 1)


class Pattern(Domain):
    def __init__(self, pattern, describe):
        self.pattern, self.text = re.compile(pattern), describe

    def check(self, value, arguments):
        return None if self.pattern.match(value) else 'expected ' + self.text


class NameList(Domain):
    """Comma-separated absolute names (/sphere2/terrain_plant, ...)."""

    def check(self, value, arguments):
        if all(ABSOLUTE_NAME.match(n.strip()) for n in value.split(',')):
            return None
        return 'expected comma-separated absolute node names, e.g. /sphere2/terrain_plant'


class ExistingFile(Domain):
    """A file that exists. A relative path is relative to where roslaunch runs, as for
    roslaunch's own file= (absolute=True: for a node's argument, which the node, started in
    ROS_HOME, would read elsewhere)."""

    def __init__(self, describe, absolute=False):
        self.text, self.absolute = describe, absolute

    def check(self, value, arguments):
        if os.path.isfile(value) and (os.path.isabs(value) or not self.absolute):
            return None
        which = 'the absolute path to an' if self.absolute else 'an'
        return 'expected %s (%s existing file)' % (self.text, which)


class Record(Domain):
    """A bag to write (FILE.bag), or else (directory=True) a directory for a time-stamped bag.
    A relative path is relative to ROS_HOME, where roslaunch starts the recorder, so only an
    absolute one is checked for its directory."""

    def __init__(self, directory):
        self.directory = directory

    def check(self, value, arguments):
        is_bag = value.endswith('.bag')
        where = os.path.dirname(value) if is_bag else value
        if ((is_bag or self.directory) and re.match(r'^\S+$', value)
                and (not os.path.isabs(value) or os.path.isdir(where))):
            return None
        return ('expected FILE.bag%s (no blanks; a relative path is relative to ROS_HOME)'
                % (' or an existing directory for a time-stamped bag' if self.directory else ''))


class Hardware(Domain):
    """sim, loopback, none (stacks only), NAME for launch/hardware/NAME.launch, or a driver's
    launch file."""

    def __init__(self, none_allowed):
        self.none_allowed = none_allowed

    def check(self, value, arguments):
        if value.endswith('.launch'):
            if os.path.isabs(value) and os.path.isfile(value):
                return None
        elif value == 'none' and self.none_allowed:
            return None
        elif RELATIVE_NAME.match(value) and os.path.isfile(
                os.path.join(package_path(), 'launch', 'hardware', value + '.launch')):
            return None
        drivers = sorted(os.path.splitext(f)[0] for f in
                         os.listdir(os.path.join(package_path(), 'launch', 'hardware'))
                         if f.endswith('.launch'))
        return 'expected %s%s or an absolute path to an existing driver.launch' % (
            ', '.join(drivers), ', none' if self.none_allowed else '')


class ActuatorModels(Domain):
    """none, or a YAML file of actuator models for a driver that takes them (not loopback)."""

    FILE = Optional(ExistingFile('a YAML file of actuator models'))

    def check(self, value, arguments):
        if value != 'none' and arguments.get('hardware') == 'loopback':
            return 'expected none with hardware:=loopback (that driver has no actuator models)'
        return self.FILE.check(value, arguments)


class Part(Domain):
    """Which half of a stack this host runs. Nodelets share one process, which cannot span two
    hosts."""

    CHOICE = Choice('all', 'robot', 'workstation')

    def check(self, value, arguments):
        if value != 'all' and arguments.get('nodelet', 'false').lower() in ('true', '1'):
            return 'expected all with nodelet:=true (one nodelet manager cannot span two hosts)'
        return self.CHOICE.check(value, arguments)


class YamlOf(Domain):
    def __init__(self, kind, describe):
        self.kind, self.text = kind, describe

    def check(self, value, arguments):
        try:
            parsed = yaml.safe_load(value)
        except yaml.YAMLError:
            parsed = None
        return None if isinstance(parsed, self.kind) else 'expected ' + self.text


def package_path():
    # scripts/ of the package, in the source tree or installed in its share directory
    return os.path.dirname(os.path.dirname(os.path.realpath(__file__)))


def modules_plus_one(arguments):
    modules = parse_number(arguments.get('modules', ''))
    return int(modules) + 1 if modules is not None else None


BOOLEAN = Boolean()
DURATION = Number(minimum=0, unit='s, simulated; 0 = forever')
NAME_PART = Pattern(r'^[A-Za-z0-9_.+-]+$', 'letters, digits and _.+- (a part of a file name)')

# Every argument of every launch file, by name.
DOMAINS = {
    # The stacks
    'robot': Choice('3R', '2R', 'RT', 'RS'),
    'path': Choice('circle', 'diamond', 'topic'),
    'terrain': Optional(ExistingFile('a height map YAML', absolute=True)),
    'untimed_speed': Optional(Number(above=0, unit='m/s')),
    'model': Choice('paper', 'rolling'),
    'law': Choice('smooth', 'paper'),
    'mode': Choice('tracking', 'teleop'),
    'clock': Choice('lockstep', 'free', 'wall'),
    'speedup': Speedup(),
    'duration': DURATION,
    'rviz': BOOLEAN,
    'ns': Pattern(RELATIVE_NAME.pattern, 'a relative ROS namespace, e.g. sphere'),
    'frame_prefix': Pattern(r'^(%s/)*$' % NAME, "empty or names ending in '/', e.g. sphere/"),
    'record': Optional(Record(directory=True)),
    'owns_clock': BOOLEAN,
    'clock_leader': Optional(Pattern(ABSOLUTE_NAME.pattern, 'an absolute namespace, e.g. /sphere')),
    'clock_followers': Optional(NameList()),
    'hardware': Hardware(none_allowed=True),
    'actuator_models': ActuatorModels(),
    'nodelet': BOOLEAN,
    'low_latency': BOOLEAN,
    'loop_cpu': LoopCpu(),
    'respawn': BOOLEAN,
    'wait_for_subscribers': Number(minimum=0, whole=True),
    'part': Part(),
    'odom': Pattern(r'^/?%s(/%s)*$' % (NAME, NAME), 'a topic name, relative or absolute, e.g. odom or /ekf/odom'),
    'origin_x': Number(unit='m'),
    'origin_y': Number(unit='m'),
    'origin_yaw': Number(unit='rad'),
    'sensors': Optional(ExistingFile('a YAML file of odometry noise and IMU settings')),
    # Norma
    'controller': Choice('paper', 'tracking'),
    'variant': Choice('text', 'appendix'),
    'max_torque': Number(above=0, unit='N m'),
    'max_force': Number(above=0, unit='N'),
    # The two-rotor sphere
    'k': Number(above=0),
    'steps': Number(minimum=1, whole=True),
    'target': NumberList(3, describe='u,v,psi: three numbers [m, m, rad], e.g. 0.05,0.03,0.4'),
    'curve_rate': Number(above=0, unit='rad/s'),
    'actuator_time_constant': Number(minimum=0, unit='s'),
    'corrections': Number(minimum=0, whole=True),
    'correction_tolerance': Number(above=0, unit='m'),
    'correction_tilt_tolerance': Number(above=0, unit='rad'),
    'execute': BOOLEAN,
    # FreeBOT
    'modules': Number(minimum=1, whole=True),
    'radius': Number(above=0, unit='m'),
    'radii': Optional(NumberList(modules_plus_one, above=0, yaml_list=True,
                                 describe='a list of modules + 1 radii > 0 [m], e.g. '
                                          '"[0.04, 0.034, 0.034, 0.034, 0.034]"')),
    'sequence': BOOLEAN,
    'dwell': Number(minimum=0, unit='s'),
    # record.launch and replay.launch
    'stack': Choice('terrain', 'roller', 'norma', 'rotor', 'freebot'),
    'scenario': NAME_PART,
    'dir': Pattern(r'^[^\s]+$', 'a directory (no blanks)'),
    'compression': Choice('none', 'lz4', 'bz2'),
    'respawn_rviz': BOOLEAN,
    'rviz_frame_rate': Optional(Number(above=0, unit='frames/s')),
    'loop': BOOLEAN,
    'rate': Number(above=0),
    'start': Number(minimum=0, unit='s'),
    'topics': Pattern(r'^(all|/\S+(\s+/\S+)*)$', 'all or space-separated absolute topic names'),
    'rsp': BOOLEAN,
    'required': BOOLEAN,
    'delay': Number(minimum=0, unit='s'),
    # launch/hardware.launch and launch/hardware/*.launch
    'actuators': YamlOf(list, 'a YAML list of actuator names, e.g. [theta, phi, psi]'),
    'max_velocity': Number(above=0, unit='rad/s'),
    'max_acceleration': Number(above=0, unit='rad/s^2'),
    'command_timeout': Number(above=0, unit='s'),
    'models': Optional(ExistingFile('a YAML file of actuator models')),
    'effort_limits': YamlOf(dict, 'a YAML dictionary {actuator: max effort}'),
    'manager': Optional(Pattern(RELATIVE_NAME.pattern, "a nodelet manager's name")),
}

# Where a launch file gives a name another meaning.
DOMAINS_BY_FILE = {
    'record': {'robot': NAME_PART, 'bag': Optional(Record(directory=False))},
    'replay': {'bag': ExistingFile('a recorded bag', absolute=True)},
    'hardware': {'hardware': Hardware(none_allowed=False)},
    'hardware/loopback': {'models': Choice('none')},
}


def problems(launch_file, arguments):
    """(name, value, expected) for every argument outside its domain."""
    domains = dict(DOMAINS, **DOMAINS_BY_FILE.get(launch_file, {}))
    found = []
    for name, value in arguments.items():
        if name not in domains:
            raise KeyError(name)
        expected = domains[name].check(value, arguments)
        if expected:
            found.append((name, value, expected))
    return found


def main(argv):
    if len(argv) < 2 or any('=' not in a for a in argv[2:]):
        sys.stderr.write('usage: check_launch_arguments.py LAUNCH_FILE NAME=VALUE...\n')
        return 2
    launch_file = argv[1]
    arguments = dict(a.split('=', 1) for a in argv[2:])
    try:
        found = problems(launch_file, arguments)
    except KeyError as unknown:
        sys.stderr.write('check_launch_arguments.py: launch/%s.launch passes argument %s, which '
                         'has no domain here\n' % (launch_file, unknown))
        return 2
    for name, value, expected in found:
        sys.stderr.write("argument '%s' = '%s': %s\n" % (name, value, expected))
    if found:
        sys.stderr.write('(launch/%s.launch: nothing was started; `roslaunch --ros-args` lists its '
                         'arguments)\n' % launch_file)
        return 1
    sys.stdout.write(yaml.safe_dump(arguments, default_flow_style=False))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
