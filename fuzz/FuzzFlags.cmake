# Compile flags of a fuzzing build (KERF_BUILD_FUZZERS=ON): every Kerf object is instrumented for
# libFuzzer's coverage feedback and checked by ASan and UBSan; fuzz/CMakeLists.txt links the engine.
if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "KERF_BUILD_FUZZERS needs clang (libFuzzer): cmake --preset fuzz, or CXX=clang++")
endif()
set(KERF_SANITIZE -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
add_compile_options(-fsanitize=fuzzer-no-link ${KERF_SANITIZE})
add_link_options(${KERF_SANITIZE})
