cmake_minimum_required(VERSION 3.25)  # if(IN_LIST)
# Which programs load Bluetooth's libraries (ldd: every shared library, however reached).
# PROGRAMS: name=path entries, comma-separated; WITH_NXT: the build's LEGOFEUP_WITH_NXT. With
# the NXT, what drives a brick (the CLI, the emulator, the GUI) loads BlueZ and the GUI Qt
# Bluetooth too — so the check is seen to find them when they are there; without it, no
# program loads either. legofeup-sim loads neither in any build.
string(REPLACE "," ";" PROGRAMS "${PROGRAMS}")
set(bluez "libbluetooth\\.so")
set(qt_bluetooth "libQt6Bluetooth\\.so")

foreach(entry IN LISTS PROGRAMS)
    string(REGEX REPLACE "=.*" "" name "${entry}")
    string(REGEX REPLACE "^[^=]*=" "" path "${entry}")
    execute_process(COMMAND ${LDD} "${path}" RESULT_VARIABLE result OUTPUT_VARIABLE libraries
                    ERROR_VARIABLE error)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "ldd ${path} failed: ${result} ${error}")
    endif()
    set(expected)
    if(WITH_NXT AND name MATCHES "^legofeup(-cli|-nxt-emu)?$")
        list(APPEND expected ${bluez})
    endif()
    if(WITH_NXT AND name STREQUAL "legofeup")
        list(APPEND expected ${qt_bluetooth})
    endif()
    foreach(library ${bluez} ${qt_bluetooth})
        string(REGEX MATCH "${library}" found "${libraries}")
        if(library IN_LIST expected AND NOT found)
            message(FATAL_ERROR "${name} does not load ${library} in a build with the NXT:\n"
                                "${libraries}")
        endif()
        if(found AND NOT library IN_LIST expected)
            message(FATAL_ERROR "${name} loads ${found}, which it must not with "
                                "LEGOFEUP_WITH_NXT=${WITH_NXT}:\n${libraries}")
        endif()
    endforeach()
    message(STATUS "${name} loads of Bluetooth's libraries what it should: [${expected}]")
endforeach()
