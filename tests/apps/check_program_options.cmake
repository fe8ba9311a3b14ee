# The default suite's check of one program's options and outputs: its --help read once, then a
# subset of the option table (check_options.cmake) and of the output collisions
# (check_outputs.cmake): three program starts. The full tables run under the label long.
#   cmake -DAPP=<exe> -DNAME=<program> -DWORK=<dir> -DMIN_OPTIONS=n -DMIN_OUTPUTS=n -P check_program_options.cmake
include(${CMAKE_CURRENT_LIST_DIR}/help_options.cmake)
fog_help_options(${APP} help)
set(help_parsed ON)
set(SUBSET ON)
include(${CMAKE_CURRENT_LIST_DIR}/check_options.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/check_outputs.cmake)
