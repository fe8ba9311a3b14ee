# The installed API is mrpt_fog/include/ alone: no public header may include an internal one
# (mrpt_fog/internal/, not installed) or anything else of ours that is not public.
add_test(NAME package.public_headers_standalone COMMAND ${CMAKE_COMMAND}
  -DINCLUDE_DIR=${FOG_SOURCE_DIR}/mrpt_fog/include -P ${FOG_SOURCE_DIR}/cmake/CheckPublicHeaders.cmake)
set_tests_properties(package.public_headers_standalone PROPERTIES LABELS package)
