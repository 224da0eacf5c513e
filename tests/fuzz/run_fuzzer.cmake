# SPDX-License-Identifier: Apache-2.0
# One bounded libFuzzer run: the committed seeds are copied to a scratch
# corpus, the fuzzer runs SECONDS on it (new inputs go to the scratch copy),
# and a crash leaves its input in WORK/crashes/ and fails the test.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/corpus ${WORK}/crashes)
file(GLOB seeds ${SEEDS}/*)
file(COPY ${seeds} DESTINATION ${WORK}/corpus)
execute_process(
  COMMAND ${FUZZER} -max_total_time=${SECONDS} -rss_limit_mb=1024 -timeout=10 -max_len=65536
          -print_final_stats=1 -artifact_prefix=${WORK}/crashes/ ${WORK}/corpus
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "fuzzer failed (${result}): the input is in ${WORK}/crashes/")
endif()
