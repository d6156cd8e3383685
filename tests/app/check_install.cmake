# Installs the build into PREFIX and checks what a desktop finds there, then starts the
# installed application offscreen: it must show its window and save a picture of it.
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${PREFIX}"
                RESULT_VARIABLE result OUTPUT_QUIET)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "cmake --install failed: ${result}")
endif()

set(installed bin/legofeup bin/legofeup-cli bin/legofeup-sim
    share/applications/legofeup-lab.desktop share/icons/hicolor/scalable/apps/legofeup-lab.svg)
if(WITH_NXT)
    list(APPEND installed bin/legofeup-nxt-emu)
endif()
foreach(file IN LISTS installed)
    if(NOT EXISTS "${PREFIX}/${file}")
        message(FATAL_ERROR "not installed: ${file}")
    endif()
endforeach()

file(READ "${PREFIX}/share/applications/legofeup-lab.desktop" desktop)
foreach(line "[Desktop Entry]" "Type=Application" "Exec=legofeup" "Icon=legofeup-lab")
    string(FIND "${desktop}" "${line}" at)
    if(at EQUAL -1)
        message(FATAL_ERROR "the desktop file lacks '${line}'")
    endif()
endforeach()

set(ENV{QT_QPA_PLATFORM} offscreen)
set(ENV{XDG_CONFIG_HOME} "${PREFIX}/config")
execute_process(
    COMMAND "${PREFIX}/bin/legofeup" --start --speed 10 --screenshot "${PREFIX}/window.png"
            --screenshot-after 2
    RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
if(NOT result EQUAL 0 OR NOT EXISTS "${PREFIX}/window.png")
    message(FATAL_ERROR "the installed legofeup did not start: ${result}\n${out}\n${err}")
endif()
file(READ "${PREFIX}/window.png" signature LIMIT 4 HEX)
if(NOT signature STREQUAL "89504e47")
    message(FATAL_ERROR "window.png is not a PNG")
endif()
execute_process(COMMAND "${PREFIX}/bin/legofeup" --version
                RESULT_VARIABLE result OUTPUT_VARIABLE version)
if(NOT result EQUAL 0 OR NOT version MATCHES "LegoFeup Lab")
    message(FATAL_ERROR "legofeup --version: ${result} ${version}")
endif()
