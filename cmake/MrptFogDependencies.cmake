# The project's fixed dependencies (Debian bookworm packages; see scripts/setup.sh).
find_package(mrpt-obs REQUIRED)        # CObservation, CObservationIMU/RawDAQ/Odometry
find_package(mrpt-io REQUIRED)         # gz streams
find_package(mrpt-serialization REQUIRED)
find_package(mrpt-containers REQUIRED) # mrpt::containers::yaml (calibration and profile files)
find_package(mrpt-poses REQUIRED)
find_package(mrpt-math REQUIRED)
find_package(mrpt-system REQUIRED)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(OpenCV 4 REQUIRED COMPONENTS core imgproc imgcodecs)
find_package(Threads REQUIRED)
find_package(ZLIB REQUIRED)              # crc32 of the gzip trailer check

# MRPT ships TCLAP (command-line parsing) as headers without a CMake package.
find_path(MRPT_TCLAP_INCLUDE_DIR mrpt/3rdparty/tclap/CmdLine.h
  PATHS /usr/include/mrpt/tclap/include REQUIRED)
add_library(fog_tclap INTERFACE)
target_include_directories(fog_tclap SYSTEM INTERFACE ${MRPT_TCLAP_INCLUDE_DIR})
