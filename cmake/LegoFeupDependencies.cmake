# The architecture's dependency rules (docs/architecture.md), enforced at configure time.
#
# legofeup_restrict_links(<target> ALLOWED <lib>...) checks, once every directory has been
# processed, that <target> links nothing but the listed libraries (and other project targets
# named in ALLOWED). A violation stops the configure step with the reason.
function(legofeup_restrict_links target)
    cmake_parse_arguments(PARSE_ARGV 1 ARG "" "" "ALLOWED")
    cmake_language(EVAL CODE "
        cmake_language(DEFER DIRECTORY \"${CMAKE_SOURCE_DIR}\"
            CALL _legofeup_check_links \"${target}\" \"${ARG_ALLOWED}\")")
endfunction()

function(_legofeup_check_links target allowed)
    foreach(property LINK_LIBRARIES INTERFACE_LINK_LIBRARIES)
        get_target_property(links ${target} ${property})
        if(NOT links)
            continue()
        endif()
        foreach(lib IN LISTS links)
            # Generator expressions such as $<LINK_ONLY:x> wrap a plain name.
            string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" lib "${lib}")
            if(NOT lib IN_LIST allowed)
                message(FATAL_ERROR "${target} may link only [${allowed}], but links '${lib}' "
                                    "(see docs/architecture.md)")
            endif()
        endforeach()
    endforeach()
endfunction()
