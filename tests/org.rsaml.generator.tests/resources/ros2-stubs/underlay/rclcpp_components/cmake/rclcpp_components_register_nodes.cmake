# SPDX-License-Identifier: EPL-2.0
# As rclcpp_components_register_nodes(<library> <class>...) of rclcpp_components: registers the
# classes as components of the library. rclcpp finds them by name at run time; this makes, per class,
# an executable that refers to it, so that linking fails when the library does not register that
# class with RCLCPP_COMPONENTS_REGISTER_NODE.
macro(rclcpp_components_register_nodes target)
  set(_index 0)
  foreach(_plugin ${ARGN})
    math(EXPR _index "${_index} + 1")
    if(_plugin MATCHES "^(.*)::([A-Za-z_][A-Za-z0-9_]*)$")
      set(_declaration "namespace ${CMAKE_MATCH_1} { class ${CMAKE_MATCH_2}; }")
    else()
      set(_declaration "class ${_plugin};")
    endif()
    set(_main "${CMAKE_CURRENT_BINARY_DIR}/rclcpp_components/registered_${_index}.cpp")
    file(WRITE "${_main}"
      "${_declaration}\n"
      "namespace rclcpp_components { template <typename NodeT> bool registered(); }\n"
      "int main() { return rclcpp_components::registered<${_plugin}>() ? 0 : 1; }\n")
    add_executable(${target}_registered_${_index} "${_main}")
    target_link_libraries(${target}_registered_${_index} ${target})
  endforeach()
endmacro()
