# The architecture's dependency rules (docs/architecture.md), enforced at configure time.
#
# legofeup_restrict_links(<target> ALLOWED <lib>...) checks, once every directory has been
# processed, that <target> links nothing but the listed libraries (and other project targets
# named in ALLOWED). A violation stops the configure step with the reason.
function(legofeup_restrict_links target)
    cmake_parse_arguments(PARSE_ARGV 1 ARG "" "" "ALLOWED")
    _legofeup_defer_link_check(_legofeup_check_links ${target} "${ARG_ALLOWED}")
endfunction()

# legofeup_forbid_links(<target> FORBIDDEN <lib>...) checks, once every directory has been
# processed, that <target> reaches none of the listed libraries: not directly, nor through any
# target it links, however deep. The allow-lists state what each target links; this says what
# must stay out of everything below a target (the NXT, below reports and grading), so that a
# new link further down cannot bring it in unnoticed. A name that is no target in this build
# (the NXT's in one without it) is still checked: nothing may link it by that name either.
function(legofeup_forbid_links target)
    cmake_parse_arguments(PARSE_ARGV 1 ARG "" "" "FORBIDDEN")
    _legofeup_defer_link_check(_legofeup_check_forbidden_links ${target} "${ARG_FORBIDDEN}")
endfunction()

# What a build with the NXT (LEGOFEUP_WITH_NXT) adds, by every name it can be linked by: its
# driver, its runs, the emulated brick, BlueZ, Qt Bluetooth and the D-Bus Qt reaches BlueZ over.
set(LEGOFEUP_NXT_LIBRARIES
    legofeup::comms_nxt legofeup_comms_nxt legofeup::lessons_nxt legofeup_lessons_nxt
    legofeup::nxtemu legofeup_nxtemu PkgConfig::BLUEZ Qt6::Bluetooth Qt6::DBus)

# Calls <check>(<target> <libraries>) once every directory has been processed, when every
# target has all its links.
function(_legofeup_defer_link_check check target libraries)
    cmake_language(EVAL CODE "
        cmake_language(DEFER DIRECTORY \"${CMAKE_SOURCE_DIR}\"
            CALL ${check} \"${target}\" \"${libraries}\")")
endfunction()

# What <target> links directly (LINK_LIBRARIES and INTERFACE_LINK_LIBRARIES), into <out>.
function(_legofeup_direct_links target out)
    set(direct)
    foreach(property LINK_LIBRARIES INTERFACE_LINK_LIBRARIES)
        get_target_property(links ${target} ${property})
        if(NOT links)
            continue()
        endif()
        foreach(lib IN LISTS links)
            # Generator expressions such as $<LINK_ONLY:x> wrap a plain name.
            string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" lib "${lib}")
            list(APPEND direct "${lib}")
        endforeach()
    endforeach()
    set(${out} "${direct}" PARENT_SCOPE)
endfunction()

function(_legofeup_check_links target allowed)
    _legofeup_direct_links(${target} links)
    foreach(lib IN LISTS links)
        if(NOT lib IN_LIST allowed)
            message(FATAL_ERROR "${target} may link only [${allowed}], but links '${lib}' "
                                "(see docs/architecture.md)")
        endif()
    endforeach()
endfunction()

function(_legofeup_check_forbidden_links target forbidden)
    set(seen)
    set(queue ${target})
    while(queue)
        list(POP_FRONT queue current)
        if(current IN_LIST seen)
            continue()
        endif()
        list(APPEND seen ${current})
        _legofeup_direct_links(${current} links)
        foreach(lib IN LISTS links)
            if(lib IN_LIST forbidden)
                message(FATAL_ERROR "${target} must not link '${lib}', but ${current} does "
                                    "(see docs/architecture.md)")
            endif()
            if(TARGET ${lib})  # a target seen from the top directory: what it links too
                list(APPEND queue ${lib})
            endif()
        endforeach()
    endwhile()
endfunction()
