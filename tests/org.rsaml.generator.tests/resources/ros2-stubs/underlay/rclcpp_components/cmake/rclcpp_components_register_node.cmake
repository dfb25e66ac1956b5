# SPDX-License-Identifier: EPL-2.0
# As rclcpp_components_register_node(<library> PLUGIN <class> EXECUTABLE <name>) of rclcpp_components:
# an executable that runs the component the library registers. rclcpp's executable loads the class
# by name at run time; this one refers to it, so that linking fails when the library does not
# register that class with RCLCPP_COMPONENTS_REGISTER_NODE.
macro(rclcpp_components_register_node target)
  cmake_parse_arguments(_ARG "" "PLUGIN;EXECUTABLE;EXECUTOR;RESOURCE_INDEX" "" ${ARGN})
  if(NOT _ARG_PLUGIN OR NOT _ARG_EXECUTABLE)
    message(FATAL_ERROR "rclcpp_components_register_node() needs PLUGIN and EXECUTABLE")
  endif()
  if(_ARG_PLUGIN MATCHES "^(.*)::([A-Za-z_][A-Za-z0-9_]*)$")
    set(_ns "${CMAKE_MATCH_1}")
    set(_class "${CMAKE_MATCH_2}")
    set(_declaration "namespace ${_ns} { class ${_class}; }")
  else()
    set(_declaration "class ${_ARG_PLUGIN};")
  endif()
  set(_main "${CMAKE_CURRENT_BINARY_DIR}/rclcpp_components/node_main_${_ARG_EXECUTABLE}.cpp")
  file(WRITE "${_main}"
    "${_declaration}\n"
    "namespace rclcpp_components { template <typename NodeT> bool registered(); }\n"
    "int main() { return rclcpp_components::registered<${_ARG_PLUGIN}>() ? 0 : 1; }\n")
  add_executable(${_ARG_EXECUTABLE} "${_main}")
  target_link_libraries(${_ARG_EXECUTABLE} ${target})
  install(TARGETS ${_ARG_EXECUTABLE} DESTINATION lib/${PROJECT_NAME})
endmacro()
