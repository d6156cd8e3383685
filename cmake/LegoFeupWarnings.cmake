# Warnings for every target of the project: `legofeup_enable_warnings(target)`.
# LEGOFEUP_WARNINGS_AS_ERRORS (the `dev` and `asan` presets turn it on) makes them errors.
option(LEGOFEUP_WARNINGS_AS_ERRORS "Treat compiler warnings as errors" OFF)

function(legofeup_enable_warnings target)
    target_compile_options(${target} PRIVATE
        -Wall -Wextra -Wpedantic
        -Wshadow -Wconversion -Wsign-conversion -Wold-style-cast
        -Wnon-virtual-dtor -Woverloaded-virtual -Wcast-align
        -Wnull-dereference -Wdouble-promotion -Wformat=2
        -Wimplicit-fallthrough -Wmisleading-indentation)
    # GCC's own checks (clang, which the dev and asan presets use, does not know them; the
    # release build, which CI fails on any warning, runs them).
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
        target_compile_options(${target} PRIVATE
            -Wduplicated-cond -Wduplicated-branches -Wlogical-op -Wuseless-cast)
    endif()
    # GCC 12 reports impossible overlaps in std::string concatenation at -O2/-O3 (GCC bug
    # 105651, fixed in GCC 13); the warning is noise there, so it is off for GCC 12 only.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
        target_compile_options(${target} PRIVATE -Wno-restrict)
    endif()
    # In a unity build a source file is #included into the batch's translation unit, so GCC
    # takes a class defined in it for one defined in a header and warns when the class holds
    # a type from the file's anonymous namespace. Each source is still included exactly
    # once, so the one-definition rule the warning protects cannot be broken this way.
    if(LEGOFEUP_UNITY_BUILD AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
        target_compile_options(${target} PRIVATE -Wno-subobject-linkage)
    endif()
    if(LEGOFEUP_WARNINGS_AS_ERRORS)
        target_compile_options(${target} PRIVATE -Werror)
    endif()
endfunction()
