# The user documentation: relative links in README.md, CHANGELOG.md and docs/ resolve (files and
# heading anchors); README.md and docs/ outside docs/validation/ hold no date and no commit id of
# this repository; README.md is at most 150 lines with its first command within 40 lines.
# The validation figures' table parses and names a command for each figure (validate.sh --list).
find_package(Python3 COMPONENTS Interpreter QUIET)
if(Python3_Interpreter_FOUND)
  add_test(NAME docs.check_links_and_user_docs COMMAND ${Python3_EXECUTABLE} ${FOG_SOURCE_DIR}/scripts/check-docs.py ${FOG_SOURCE_DIR})
  set_tests_properties(docs.check_links_and_user_docs PROPERTIES LABELS "docs;integration" TIMEOUT 60)
endif()
add_test(NAME docs.validate_list COMMAND ${FOG_SOURCE_DIR}/scripts/validate.sh --list)
set_tests_properties(docs.validate_list PROPERTIES LABELS "docs;integration" TIMEOUT 60
  PASS_REGULAR_EXPRESSION "run_b_gain_one_run")
