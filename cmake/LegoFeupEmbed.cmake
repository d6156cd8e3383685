# legofeup_embed_text(<target> <file> <namespace-qualified variable> <header name>)
# legofeup_embed_binary(<target> <file> <namespace-qualified variable> <header name>)
#
# Builds a file into <target> as `extern const std::string_view <variable>`, declared in the
# generated header <header name>, so programs need no installed data files. The file is a
# configure dependency: editing it regenerates the source. Text files become a raw string;
# files that may hold any byte (the maps' PGM images) an array of bytes.

# Writes the header declaring <variable> and the source defining it (`definition` is the
# source's text inside the namespace, given `name`), and adds the source to <target>.
function(_legofeup_embed target file variable header definition_template)
    string(REGEX MATCH "^(.*)::([^:]+)$" _ "${variable}")
    set(namespace "${CMAKE_MATCH_1}")
    set(name "${CMAKE_MATCH_2}")
    string(REPLACE "@NAME@" "${name}" definition "${definition_template}")
    set(out_dir "${CMAKE_CURRENT_BINARY_DIR}/embedded")
    file(RELATIVE_PATH relative "${PROJECT_SOURCE_DIR}" "${file}")
    file(WRITE "${out_dir}/${header}.in"
        "#pragma once\n// Generated from ${relative} by cmake/LegoFeupEmbed.cmake.\n"
        "#include <string_view>\nnamespace ${namespace} {\nextern const std::string_view ${name};\n}\n")
    file(WRITE "${out_dir}/${name}.cpp.in"
        "// Generated from ${relative} by cmake/LegoFeupEmbed.cmake.\n"
        "#include \"${header}\"\nnamespace ${namespace} {\n${definition}}\n")
    configure_file("${out_dir}/${header}.in" "${out_dir}/${header}" COPYONLY)
    configure_file("${out_dir}/${name}.cpp.in" "${out_dir}/${name}.cpp" COPYONLY)
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${file}")
    target_sources(${target} PRIVATE "${out_dir}/${name}.cpp")
    target_include_directories(${target} PRIVATE "${out_dir}")
endfunction()

function(legofeup_embed_text target file variable header)
    file(READ "${file}" content)
    string(FIND "${content}" ")legofeup_text\"" clash)
    if(NOT clash EQUAL -1)
        message(FATAL_ERROR "${file} contains the raw-string delimiter used to embed it")
    endif()
    _legofeup_embed(${target} "${file}" "${variable}" "${header}"
        "const std::string_view @NAME@ = R\"legofeup_text(${content})legofeup_text\";\n")
endfunction()

function(legofeup_embed_binary target file variable header)
    file(READ "${file}" hex HEX)
    string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
    _legofeup_embed(${target} "${file}" "${variable}" "${header}"
        "namespace {\nconst unsigned char @NAME@Bytes[] = {${bytes}};\n}\nconst std::string_view @NAME@(reinterpret_cast<const char*>(@NAME@Bytes), sizeof @NAME@Bytes);\n")
endfunction()
