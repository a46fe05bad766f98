# Fault cases: runs (see CMakeLists.txt beside this file). Each takes 10-60 s on 2 cores.
fault_case(run_same_name run_same_name.sh)
fault_case(run_full_disk run_full_disk.sh)
fault_case(run_kill_restart run_kill_restart.sh)
