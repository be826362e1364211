# The Python package of the rostest scripts' shared helpers (src/spherical_robots_testing),
# installed by catkin_python_setup() in CMakeLists.txt; not to be run by hand.
from setuptools import setup

from catkin_pkg.python_setup import generate_distutils_setup

setup(**generate_distutils_setup(packages=['spherical_robots_testing'], package_dir={'': 'src'}))
