# SPDX-License-Identifier: Apache-2.0
# Builds and runs the Slocum decoder's libFuzzer target (tests/fuzz/
# fuzz_slocum_binary.cpp) for a bounded time, standalone: clang++ with
# ASan + UBSan + libFuzzer on the reader's sources, seeds copied from
# tests/fuzz/corpus/slocum_binary into a scratch directory. A crash fails the
# test and leaves its input in WORK/crashes.
#   cmake -DCLANGXX=... -DSOURCE=<repo> -DWORK=<dir> -DSECONDS=20 -P fuzz_slocum_binary.cmake
file(MAKE_DIRECTORY ${WORK}/corpus ${WORK}/crashes)
file(GLOB seeds ${SOURCE}/tests/fuzz/corpus/slocum_binary/*)
file(COPY ${seeds} DESTINATION ${WORK}/corpus)
file(GLOB reader_sources ${SOURCE}/tools/slocum/src/ascii_header.cpp ${SOURCE}/tools/slocum/src/binary_file.cpp
     ${SOURCE}/tools/slocum/src/cycle_decoder.cpp ${SOURCE}/tools/slocum/src/lat_lon.cpp
     ${SOURCE}/tools/slocum/src/lz4_blocks.cpp ${SOURCE}/tools/slocum/src/sensor_cache.cpp)
execute_process(
  COMMAND ${CLANGXX} -std=c++20 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined
          -DGLIDER_SOURCE_DIR="${SOURCE}" -I${SOURCE}/tools/slocum/include -I${SOURCE}/tools/slocum/src
          ${SOURCE}/tests/fuzz/fuzz_slocum_binary.cpp ${reader_sources} -llz4 -o ${WORK}/fuzz_slocum_binary
  RESULT_VARIABLE built)
if(NOT built EQUAL 0)
  message(FATAL_ERROR "fuzz_slocum_binary: build failed")
endif()
execute_process(
  COMMAND ${WORK}/fuzz_slocum_binary -max_total_time=${SECONDS} -rss_limit_mb=1024 -artifact_prefix=${WORK}/crashes/
          ${WORK}/corpus
  RESULT_VARIABLE ran)
if(NOT ran EQUAL 0)
  message(FATAL_ERROR "fuzz_slocum_binary found a crash: ${WORK}/crashes")
endif()
