# Runs one libFuzzer target for fuzz-smoke from an empty working corpus, so that every run
# (a developer's repeated runs and CI's fresh clone alike) starts from the same state: the
# committed seed corpus, the fixed -seed and the same cap on executions.
# Arguments (-D): FUZZER, WORK_DIR, SEED_CORPUS, SECONDS, SEED, RUNS.
file(REMOVE_RECURSE "${WORK_DIR}/corpus")
file(MAKE_DIRECTORY "${WORK_DIR}/corpus" "${WORK_DIR}/artifacts")
execute_process(COMMAND "${FUZZER}" -max_total_time=${SECONDS} -runs=${RUNS} -seed=${SEED}
                        -rss_limit_mb=2048 -timeout=10 -print_final_stats=1
                        -artifact_prefix=${WORK_DIR}/artifacts/ "${WORK_DIR}/corpus" "${SEED_CORPUS}"
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${FUZZER} failed (${result}); the input is in ${WORK_DIR}/artifacts/")
endif()
