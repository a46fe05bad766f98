# Fault cases: sweeps (see CMakeLists.txt beside this file).
fault_case(sweep_two_pools sweep_two_pools.sh)
fault_case(sweep_pool_killed sweep_pool_killed.sh)
