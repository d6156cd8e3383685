# How long a clean build takes on the two cores a lab machine or CI has.
#
# Measured with the build's own timing (`.ninja_log`), a clean build spends most of its time
# parsing the same heavy headers again in every file (GoogleTest, Eigen, Qt, toml++,
# nlohmann-json) and in linking one program per test group. Two switches cut that:
#
# LEGOFEUP_UNITY_BUILD (ON in the presets): each target's sources are compiled in batches of
#   LEGOFEUP_UNITY_BATCH_SIZE files, one translation unit a batch, so the headers are parsed
#   once a batch. Every source must therefore be safe to share a translation unit with its
#   neighbours: helpers in an anonymous namespace get names of their own (the compiler
#   reports a clash as a redefinition), and no file leaves a `using namespace` or a macro for
#   the next one. Turn it off for quick incremental work on one file:
#   `cmake --preset dev -DLEGOFEUP_UNITY_BUILD=OFF`. The presets scripts/test.sh builds use
#   batches of 16 (scripts/test.sh from a clean clone on the 2-core machine, no ccache: the
#   dev phase 303 s -> 195 s, the asan build 663 s -> 438 s, the whole script ≈ 1370 -> 985 s):
#   Eigen's and GoogleTest's templates are instantiated once a batch, and fewer batches
#   instantiate them fewer times.
#   `release` keeps 8, the size GCC's warnings are checked at in CI.
# LEGOFEUP_FAST_LINKER (ON): link with lld under clang (the `dev` and `asan` presets) and with
#   gold under GCC, when the toolchain has them; GNU ld's single-threaded symbol resolution is
#   the slowest step of linking the debug-info-heavy test programs.
#
# The presets that scripts/test.sh builds use clang: it compiles this project's translation
# units in about half GCC's time (a unity batch of the estimator tests: 21 s against 49 s at
# -O0 -g, 49 s against 101 s with ASan at -O1). GCC builds `release`, so CI still builds
# and tests everything with it, and fails on any warning it prints (.ci/run).
option(LEGOFEUP_UNITY_BUILD "Compile each target's sources in batches (faster clean builds)" OFF)
set(LEGOFEUP_UNITY_BATCH_SIZE 8 CACHE STRING "Sources per translation unit in a unity build")
option(LEGOFEUP_FAST_LINKER "Link with gold when available" ON)

if(LEGOFEUP_UNITY_BUILD)
    set(CMAKE_UNITY_BUILD ON)
    set(CMAKE_UNITY_BUILD_BATCH_SIZE ${LEGOFEUP_UNITY_BATCH_SIZE})
endif()

if(LEGOFEUP_FAST_LINKER)
    include(CheckLinkerFlag)
    if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
        check_linker_flag(CXX "-fuse-ld=lld" LEGOFEUP_HAS_LLD)
        if(LEGOFEUP_HAS_LLD)
            add_link_options(-fuse-ld=lld)
        endif()
    else()
        check_linker_flag(CXX "-fuse-ld=gold" LEGOFEUP_HAS_GOLD)
        if(LEGOFEUP_HAS_GOLD)
            add_link_options(-fuse-ld=gold)
        endif()
    endif()
endif()
