# Installs the built workbench afresh into MOD_DIR (no files left over from an earlier build).
file(REMOVE_RECURSE ${MOD_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${MOD_DIR}
                OUTPUT_QUIET RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "installing the workbench into ${MOD_DIR} failed")
endif()
