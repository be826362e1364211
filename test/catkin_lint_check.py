#!/usr/bin/env python3
"""catkin_lint --strict -W2 over the package: every message, at every level, fails the test.

usage: catkin_lint_check.py SOURCE_DIR RESULT_XML

It lints a copy of the package in a directory named spherical_robots (catkin_lint notes a
package directory named otherwise, and a clone's name is its owner's choice) without colcon's
build/, install/ and log/ and the demo's results/ (catkin_lint would take the installed
programs there for uninstalled scripts of the package). The messages that remain on purpose
are ignored by pragmas in CMakeLists.txt, each with its reason. Writes a JUnit result (one test
case, the messages as its failure) for catkin's run_tests.
"""
import os
import shutil
import subprocess
import sys
import tempfile
from xml.sax.saxutils import escape

NOT_THE_PACKAGE = ('build', 'install', 'log', 'results', '.git')


def lint(source):
    with tempfile.TemporaryDirectory(prefix='catkin_lint_check.') as work:
        copy = os.path.join(work, 'spherical_robots')
        shutil.copytree(source, copy, symlinks=True,
                        ignore=lambda d, names: [n for n in names if d == source and
                                                 n in NOT_THE_PACKAGE])
        try:
            result = subprocess.run(['catkin_lint', '--strict', '-W2', copy],
                                    capture_output=True, text=True, timeout=300)
        except FileNotFoundError:
            return 1, 'catkin_lint is not installed (Debian: catkin-lint; scripts/install_deps.sh)'
    # stderr also says that rosdep's database is missing (unknown dependencies are not checked).
    return result.returncode, (result.stdout + result.stderr).replace(work + '/', '')


def write_result(path, returncode, output):
    failure = ('<failure message="catkin_lint reported problems">%s</failure>' % escape(output)
               if returncode != 0 else '')
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w') as xml:
        xml.write('<?xml version="1.0" encoding="UTF-8"?>\n'
                  '<testsuite name="catkin_lint" tests="1" failures="%d" errors="0">\n'
                  '  <testcase classname="catkin_lint" name="strict_W2">%s'
                  '<system-out>%s</system-out></testcase>\n</testsuite>\n'
                  % (1 if failure else 0, failure, escape(output)))


def main(argv):
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    returncode, output = lint(os.path.realpath(argv[1]))
    sys.stdout.write(output)
    write_result(argv[2], returncode, output)
    return returncode


if __name__ == '__main__':
    sys.exit(main(sys.argv))
