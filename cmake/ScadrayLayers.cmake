# SPDX-License-Identifier: MIT
# scadray_layer(<name> FOLDERS <folder>... [DEPENDS <layer>...] [EXCLUDE <file>...])
#
# One static library per layer of the architecture (docs/design/architecture.md), built from
# every .cpp under its folders and linking the layers below it PUBLIC. Every header and source
# under the folders is checked at build time (cmake/check_layers.cmake): an #include of a folder
# the layer does not link, directly or through a layer below, fails the build with the line that
# does it, so the layering is kept by the build, not by review. Headers of the layers it links
# are reachable because every layer includes from the project root.
function(scadray_layer name)
    cmake_parse_arguments(L "" "" "FOLDERS;DEPENDS;EXCLUDE" ${ARGN})
    set(sources "")
    set(checked "")
    foreach(folder IN LISTS L_FOLDERS)
        file(GLOB_RECURSE cpp CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${folder}/*.cpp)
        file(GLOB_RECURSE hdr CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${folder}/*.h)
        list(APPEND sources ${cpp})
        list(APPEND checked ${cpp} ${hdr})
    endforeach()
    foreach(file IN LISTS L_EXCLUDE)
        list(REMOVE_ITEM sources ${PROJECT_SOURCE_DIR}/${file})
    endforeach()
    add_library(${name} STATIC ${sources})
    target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
    target_link_libraries(${name} PUBLIC ${L_DEPENDS})

    set(allowed ${L_FOLDERS})
    foreach(dep IN LISTS L_DEPENDS)
        get_property(below GLOBAL PROPERTY SCADRAY_LAYER_FOLDERS_${dep})
        list(APPEND allowed ${below})
    endforeach()
    list(REMOVE_DUPLICATES allowed)
    set_property(GLOBAL PROPERTY SCADRAY_LAYER_FOLDERS_${name} ${allowed})

    set(config ${CMAKE_CURRENT_BINARY_DIR}/${name}_layers.cmake)
    set(stamp ${CMAKE_CURRENT_BINARY_DIR}/${name}_layers.stamp)
    file(CONFIGURE OUTPUT ${config} CONTENT [=[
set(LAYER "@name@")
set(ROOT "@PROJECT_SOURCE_DIR@")
set(ALLOWED "@allowed@")
set(FILES "@checked@")
set(STAMP "@stamp@")
]=] @ONLY)
    add_custom_command(OUTPUT ${stamp}
        COMMAND ${CMAKE_COMMAND} -DCONFIG=${config} -P ${PROJECT_SOURCE_DIR}/cmake/check_layers.cmake
        DEPENDS ${checked} ${config} ${PROJECT_SOURCE_DIR}/cmake/check_layers.cmake
        COMMENT "Checking the includes of ${name}" VERBATIM)
    add_custom_target(${name}_layers DEPENDS ${stamp})
    add_dependencies(${name} ${name}_layers)
endfunction()
