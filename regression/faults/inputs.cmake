# Fault cases: inputs (see CMakeLists.txt beside this file).
# Foreign inputs (WAMIT, BeamDyn) cut short stop with exit 2 naming the file, nothing written.
fault_case(truncated_inputs truncated_inputs.sh ${PROJECT_SOURCE_DIR})
