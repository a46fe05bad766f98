# Fault cases: runs (see CMakeLists.txt beside this file).
