# Fault cases: inputs (see CMakeLists.txt beside this file).
