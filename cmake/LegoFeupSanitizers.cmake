# AddressSanitizer + UndefinedBehaviorSanitizer for the whole build (`asan` preset).
option(LEGOFEUP_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)

if(LEGOFEUP_SANITIZE)
    add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer
                        -fno-sanitize-recover=all)
    add_link_options(-fsanitize=address,undefined)
    # GCC documents that -fsanitize=address can produce spurious -Wmaybe-uninitialized
    # warnings; GCC 12 does so inside std::variant's copy-assignment. The dev build keeps
    # the warning on, so real cases are still caught there.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
        add_compile_options(-Wno-maybe-uninitialized)
    endif()
endif()
