# sgmp_export_library(TARGET NAME): a library folder declares its own target installable.
# Its headers (the folder's include/) are found from the build tree and, once installed,
# from CMAKE_INSTALL_INCLUDEDIR; the target joins the export set sgmpTargets as sgmp::NAME,
# and the folder's include/ is installed. Called by each library folder on its own target.
function(sgmp_export_library target name)
    target_include_directories(${target} PUBLIC
        $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
        $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
    set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
    install(TARGETS ${target} EXPORT sgmpTargets
            ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
            LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
            INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
    install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
    # The Python module puts the libraries into a shared object: position-independent code.
    if(SGMP_BUILD_PYTHON)
        set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    endif()
endfunction()
