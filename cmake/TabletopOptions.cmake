# Compiler settings shared by every tabletop target, as one interface target.
#
# -ffp-contract=off keeps the compiler from fusing a*b+c into one FMA in some
# places and not others, so results do not depend on optimisation choices.
add_library(tabletop_options INTERFACE)
add_library(Tabletop::options ALIAS tabletop_options)
target_compile_features(tabletop_options INTERFACE cxx_std_17)
# The warnings are the build's own; a project using the installed
# libraries keeps its own (BUILD_INTERFACE).
target_compile_options(tabletop_options INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-ffp-contract=off>
  $<BUILD_INTERFACE:$<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow>>
  $<BUILD_INTERFACE:$<$<AND:$<BOOL:${TABLETOP_WERROR}>,$<CXX_COMPILER_ID:GNU,Clang>>:-Werror>>)

# TABLETOP_SANITIZE: AddressSanitizer (with leak checking) and
# UndefinedBehaviorSanitizer on every tabletop target; any report aborts the
# test that caused it. TABLETOP_FUZZ adds libFuzzer's coverage
# instrumentation.
if(TABLETOP_SANITIZE)
  set(tabletop_sanitizers -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  target_compile_options(tabletop_options INTERFACE ${tabletop_sanitizers}
    $<$<BOOL:${TABLETOP_FUZZ}>:-fsanitize=fuzzer-no-link>)
  target_link_options(tabletop_options INTERFACE ${tabletop_sanitizers})
  # The sanitizers' defaults and suppressions, in each executable.
  target_sources(tabletop_options INTERFACE
    $<BUILD_INTERFACE:$<$<STREQUAL:$<TARGET_PROPERTY:TYPE>,EXECUTABLE>:${PROJECT_SOURCE_DIR}/cmake/SanitizerDefaults.cpp>>)
endif()
