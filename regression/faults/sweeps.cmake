# Fault cases: sweeps (see CMakeLists.txt beside this file).
