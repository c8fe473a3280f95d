"""Prints where, under the prefix given, this Python looks for modules
(relative to the prefix): the first of its site folders under PREFIX/lib
(Debian: lib/python3/dist-packages for /usr, lib/python3.N/dist-packages for
/usr/local), else lib/python3.N/site-packages (a virtual environment's, and
the one a PYTHONPATH names). Run by cmake --install (src/python/CMakeLists.txt)
and tests/install/check.sh."""
import os
import site
import sys

prefix = os.path.normpath(sys.argv[1])
found = "lib/python%d.%d/site-packages" % sys.version_info[:2]
for folder in site.getsitepackages():
    relative = os.path.relpath(folder, prefix)
    if folder.startswith(prefix + "/lib/") and relative.count("/") == 2:
        found = relative
        break
print(found)
