# legofeup_embed_text(<target> <file> <namespace-qualified variable> <header name>)
#
# Builds a text file into <target> as `extern const std::string_view <variable>`, declared in
# the generated header <header name>, so programs need no installed data files. The file is a
# configure dependency: editing it regenerates the source.
function(legofeup_embed_text target file variable header)
    file(READ "${file}" content)
    string(FIND "${content}" ")legofeup_text\"" clash)
    if(NOT clash EQUAL -1)
        message(FATAL_ERROR "${file} contains the raw-string delimiter used to embed it")
    endif()
    string(REGEX MATCH "^(.*)::([^:]+)$" _ "${variable}")
    set(namespace "${CMAKE_MATCH_1}")
    set(name "${CMAKE_MATCH_2}")
    set(out_dir "${CMAKE_CURRENT_BINARY_DIR}/embedded")
    file(RELATIVE_PATH relative "${PROJECT_SOURCE_DIR}" "${file}")
    file(WRITE "${out_dir}/${header}.in"
        "#pragma once\n// Generated from ${relative} by cmake/LegoFeupEmbed.cmake.\n"
        "#include <string_view>\nnamespace ${namespace} {\nextern const std::string_view ${name};\n}\n")
    file(WRITE "${out_dir}/${name}.cpp.in"
        "// Generated from ${relative} by cmake/LegoFeupEmbed.cmake.\n"
        "#include \"${header}\"\nnamespace ${namespace} {\n"
        "const std::string_view ${name} = R\"legofeup_text(${content})legofeup_text\";\n}\n")
    configure_file("${out_dir}/${header}.in" "${out_dir}/${header}" COPYONLY)
    configure_file("${out_dir}/${name}.cpp.in" "${out_dir}/${name}.cpp" COPYONLY)
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${file}")
    target_sources(${target} PRIVATE "${out_dir}/${name}.cpp")
    target_include_directories(${target} PRIVATE "${out_dir}")
endfunction()
