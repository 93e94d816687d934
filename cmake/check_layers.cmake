# SPDX-License-Identifier: MIT
# Fails when a source file of a layer includes a header of a layer above it or beside it, or
# includes a third-party library outside the one folder that wraps it. Run by the build for each
# library (cmake/ScadrayLayers.cmake) with -DCONFIG=<its settings>: LAYER, ROOT, ALLOWED (the
# folders the layer may include: its own and those of every layer it links, transitively),
# FILES (its sources and headers) and STAMP (touched when all is well).
include(${CONFIG})

# Third-party headers and the one folder or file that may include each. A second room for a
# library would spread its types and its failure modes through the code.
set(rooms
    "^clipper\\.hpp$|^polyclipping/"            "importers/scad/geometry2d/"
    "^ft2build\\.h$|^freetype/|^hb\\.h$|^hb-|^harfbuzz/|^fontconfig/" "importers/scad/geometry2d/"
    "^libxml/"                                  "importers/scad/formats/"
    "^tiny_gltf\\.h$|^draco/|^meshoptimizer\\.h$" "importers/gltf/"
    "^OpenImageIO/"                             "core/image/oiio_module.cpp"
    "^png\\.h$"                                 "core/image/png_io.cpp"
    "^CLI/"                                     "tools/")

# Line number of the first occurrence of `needle` in `text`
function(line_of text needle out)
    string(FIND "${text}" "${needle}" pos)
    string(SUBSTRING "${text}" 0 ${pos} before)
    string(REGEX MATCHALL "\n" newlines "${before}")
    list(LENGTH newlines n)
    math(EXPR n "${n} + 1")
    set(${out} ${n} PARENT_SCOPE)
endfunction()

string(REPLACE ";" ", " allowed_text "${ALLOWED}")
set(errors 0)
foreach(file IN LISTS FILES)
    file(RELATIVE_PATH rel "${ROOT}" "${file}")
    file(STRINGS "${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
    foreach(line IN LISTS includes)
        if(line MATCHES "#[ \t]*include[ \t]*\"([^\"]+)\"")
            set(header "${CMAKE_MATCH_1}")
            get_filename_component(folder "${header}" DIRECTORY)
            set(ok FALSE)
            foreach(allowed IN LISTS ALLOWED)
                string(FIND "${folder}/" "${allowed}/" at)
                if(at EQUAL 0)
                    set(ok TRUE)
                    break()
                endif()
            endforeach()
            if(NOT ok)
                file(READ "${file}" text)
                line_of("${text}" "${header}" n)
                message(SEND_ERROR "${rel}:${n}: ${LAYER} may not include \"${header}\": "
                        "it may include only ${allowed_text} (see docs/design/architecture.md)")
                math(EXPR errors "${errors} + 1")
            endif()
        elseif(line MATCHES "#[ \t]*include[ \t]*<([^>]+)>")
            set(header "${CMAKE_MATCH_1}")
            set(pairs ${rooms})
            while(pairs)
                list(POP_FRONT pairs pattern room)
                if(header MATCHES "${pattern}")
                    string(FIND "${rel}" "${room}" at)
                    if(NOT at EQUAL 0)
                        file(READ "${file}" text)
                        line_of("${text}" "${header}" n)
                        message(SEND_ERROR "${rel}:${n}: <${header}> is included only in ${room}, "
                                "which wraps that library (see docs/design/architecture.md)")
                        math(EXPR errors "${errors} + 1")
                    endif()
                endif()
            endwhile()
        endif()
    endforeach()
endforeach()

if(errors GREATER 0)
    message(FATAL_ERROR "${LAYER}: ${errors} include(s) break the layering")
endif()
file(TOUCH "${STAMP}")
