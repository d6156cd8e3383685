# check_doc_images.cmake can fail: on small trees made here, a tree whose pictures are in
# order passes, and each defect it exists to catch fails it with its own message.
#   cmake -DCHECK=<check_doc_images.cmake> -DWORK=<scratch folder> -P check_doc_images_catches.cmake

cmake_minimum_required(VERSION 3.25)

# Writes a tree under WORK/NAME: README.md showing docs/images/window.png, docs/gui.md
# showing images/dialog.png and images/window.png, both pictures, and the script's table making both; then applies
# the defect DEFECT, runs the check on it and returns its output in OUTPUT, its result in RESULT.
function(check_tree name defect)
    set(root "${WORK}/${name}")
    file(REMOVE_RECURSE "${root}")
    file(WRITE "${root}/README.md" "# Lab\n\n![The window](docs/images/window.png)\n")
    file(WRITE "${root}/docs/gui.md"
         "# GUI\n\n![A dialog (modal)](images/dialog.png \"title\")\n"
         "![The window [again]](images/window.png)\n<img src=\"images/dialog.png\" width=\"50%\">\n")
    file(WRITE "${root}/docs/images/window.png" "png")
    file(WRITE "${root}/docs/images/dialog.png" "png")
    file(WRITE "${root}/scripts/screenshots.sh"
         "readonly PICTURES='\nwindow.png app estimate 60 --experiment f\n"
         "dialog.png test ui_dialog_test aTest\n'\n")
    cmake_language(EVAL CODE "${defect}")
    execute_process(COMMAND "${CMAKE_COMMAND}" -DROOT=${root} -P "${CHECK}"
                    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
    set(OUTPUT "${output}" PARENT_SCOPE)
    set(RESULT "${result}" PARENT_SCOPE)
endfunction()

set(failures "")
function(expect_pass name defect)
    check_tree(${name} "${defect}")
    if(NOT RESULT EQUAL 0)
        set(failures "${failures}\n${name}: expected to pass, failed:\n${OUTPUT}" PARENT_SCOPE)
    endif()
endfunction()
function(expect_failure name defect message)
    check_tree(${name} "${defect}")
    string(REPLACE "\n" " " flat "${OUTPUT}")
    string(REGEX REPLACE "[ \t]+" " " flat "${flat}")
    string(FIND "${flat}" "${message}" found)
    if(RESULT EQUAL 0 OR found EQUAL -1)
        set(failures "${failures}\n${name}: expected a failure saying '${message}', got "
                     "(${RESULT}):\n${OUTPUT}" PARENT_SCOPE)
    endif()
endfunction()

expect_pass(in_order "")
expect_pass(shown_in_a_sub_folder_doc
            "file(WRITE \"\${root}/docs/more/x.md\" \"![again](../images/window.png)\")")
expect_failure(shown_but_missing
               "file(REMOVE \"\${root}/docs/images/dialog.png\")"
               "docs/gui.md shows docs/images/dialog.png, which does not exist")
expect_failure(shown_but_not_made
               "file(WRITE \"\${root}/docs/images/hand.png\" \"png\")
                file(APPEND \"\${root}/docs/gui.md\" \"![by hand](images/hand.png)\n\")"
               "docs/gui.md shows hand.png, which scripts/screenshots.sh does not make")
expect_failure(shown_from_elsewhere
               "file(APPEND \"\${root}/README.md\" \"![old](pictures/old.png)\n\")"
               "which is not in docs/images/")
expect_failure(in_the_folder_but_shown_by_none
               "file(WRITE \"\${root}/docs/images/stale.png\" \"png\")"
               "docs/images/stale.png: no document shows it")
expect_failure(made_but_shown_by_none
               "file(WRITE \"\${root}/docs/gui.md\" \"# GUI, no picture\n\")
                file(REMOVE \"\${root}/docs/images/dialog.png\")"
               "scripts/screenshots.sh makes dialog.png, which no document shows")
expect_failure(made_twice
               "file(APPEND \"\${root}/scripts/screenshots.sh\" \"\")
                file(WRITE \"\${root}/scripts/screenshots.sh\"
                     \"readonly PICTURES='\nwindow.png app\ndialog.png test\nwindow.png app\n'\")"
               "scripts/screenshots.sh makes window.png twice")
expect_failure(no_table
               "file(WRITE \"\${root}/scripts/screenshots.sh\" \"#!/bin/sh\n\")"
               "no table readonly PICTURES=")

if(failures)
    message(FATAL_ERROR "check_doc_images.cmake missed a defect:${failures}")
endif()
message(STATUS "check_doc_images.cmake passes a tree in order and catches each defect")
