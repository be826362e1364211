#!/usr/bin/env python3
"""What `rosrun spherical_robots <TAB>` offers in the installed workspace: rosbash's own completion
function, run in a bash that sourced the workspace's setup.sh, must offer every node (one per
src/nodes/*.cpp), sphere_sim and every user program of scripts/ that is installed, and nothing
of test/: the rostests' programs are not installed (CMakeLists.txt says why).

Private parameter ~install_prefix: the package's install prefix (CMAKE_INSTALL_PREFIX, passed
by the add_rostest line); the colcon workspace's setup.sh sits in its parent directory.
"""
import glob
import os
import subprocess
import unittest

import rospy
import rostest

PKG = 'spherical_robots'
SOURCE = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))
COMPLETION = '/usr/share/bash-completion/completions/rosbash'


def offered(setup):
    """The words rosbash's completion offers after `rosrun spherical_robots `."""
    script = ('set +u; . "$1" && . "$2" && COMP_WORDS=(rosrun %s "") && COMP_CWORD=2 && '
              '_roscomplete_exe && printf "%%s\\n" "${COMPREPLY[@]}"' % PKG)
    # A clean environment: the devel space's variables (which name the source tree) must not leak
    # into the installed workspace's.
    env = {'PATH': '/usr/bin:/bin', 'HOME': os.environ.get('HOME', '/root')}
    result = subprocess.run(['bash', '-c', script, 'completion', setup, COMPLETION],
                            capture_output=True, text=True, env=env, timeout=60)
    if result.returncode != 0:
        raise AssertionError('completion failed (exit %d): %s' % (result.returncode, result.stderr))
    return set(result.stdout.split())


def executables(directory):
    return {os.path.basename(p) for p in glob.glob(os.path.join(directory, '*'))
            if os.path.isfile(p) and os.access(p, os.X_OK)}


class RosrunCompletion(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        prefix = rospy.get_param('~install_prefix')
        setup = os.path.join(os.path.dirname(prefix), 'setup.sh')
        if not os.path.isfile(setup):
            raise AssertionError('no setup.sh beside the install prefix %s' % prefix)
        cls.offered = offered(setup)

    def test_offers_every_node_and_user_program(self):
        nodes = {os.path.splitext(os.path.basename(p))[0]
                 for p in glob.glob(os.path.join(SOURCE, 'src', 'nodes', '*.cpp'))}
        user_programs = {p for p in executables(os.path.join(SOURCE, 'scripts'))
                         if p.endswith('.py')} & self.installed_python()
        missing = (nodes | {'sphere_sim'} | user_programs) - self.offered
        self.assertFalse(missing, 'not offered: %s (offered: %s)'
                         % (sorted(missing), sorted(self.offered)))
        self.assertTrue(user_programs, 'no user program of scripts/ is installed')

    def test_offers_nothing_of_test(self):
        tests = executables(os.path.join(SOURCE, 'test'))
        self.assertTrue(tests, 'test/ holds no program: the check would be empty')
        leaked = tests & self.offered
        self.assertFalse(leaked, 'test programs offered by rosrun: %s' % sorted(leaked))

    def installed_python(self):
        """The scripts/ programs CMakeLists.txt installs, read from its catkin_install_python."""
        with open(os.path.join(SOURCE, 'CMakeLists.txt')) as cmake:
            text = cmake.read()
        block = text[text.index('catkin_install_python(PROGRAMS'):]
        block = block[:block.index(')')]
        return {os.path.basename(w) for w in block.split() if w.startswith('scripts/')}


if __name__ == '__main__':
    rospy.init_node('rosrun_completion_check')
    rostest.rosrun(PKG, 'rosrun_completion_check', RosrunCompletion)
