/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// How the runtime's programs (a node's executable, the container, the lifecycle manager) end on a
// wrong command-line argument or parameter: one line on stderr naming the program, the argument or
// parameter, what is wrong and how to fix it, and exit status 2, instead of std::terminate.
#pragma once

#include <cstdio>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>

#include <rclcpp/rclcpp.hpp>

namespace rsaml_ros2 {

/** Exit status of a program given a wrong argument or parameter (as a command-line usage error). */
constexpr int USAGE_STATUS = 2;

/** A wrong argument or parameter of a runtime program, said with what is wrong and how to fix it. */
class UsageError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/**
 * Runs `body` (a program's main) and returns its status; a wrong argument or parameter, raised by
 * the runtime or the generated nodes (std::invalid_argument) or by rclcpp (a parameter of the wrong
 * type, an invalid value or QoS override, from a parameters file or -p; an invalid argument after
 * --ros-args), ends it
 * with "PROGRAM: what is wrong" on stderr and USAGE_STATUS.
 */
template <typename BodyT>
int run_main(int argc, char** argv, BodyT body) {
  const char* slash = argc > 0 ? std::strrchr(argv[0], '/') : nullptr;
  const std::string program = argc > 0 ? (slash != nullptr ? slash + 1 : argv[0]) : "rsaml";
  std::string wrong;
  try {
    return body();
  } catch (const rclcpp::exceptions::InvalidParameterTypeException& e) {
    wrong = std::string(e.what()) + "; give it a value of that type (in the parameters file, params_file:=, or -p)";
  } catch (const rclcpp::exceptions::InvalidParameterValueException& e) {
    wrong = std::string(e.what()) + "; give it a valid value (in the parameters file, params_file:=, or -p)";
  } catch (const rclcpp::exceptions::InvalidQosOverridesException& e) {
    wrong = std::string(e.what()) + "; correct the qos_overrides parameters (in the parameters file, params_file:=, or -p)";
  } catch (const rclcpp::exceptions::RCLInvalidROSArgsError& e) {
    wrong = std::string("invalid ROS arguments: ") + e.what() + "; correct what follows --ros-args";
  } catch (const rclcpp::exceptions::UnknownROSArgsError& e) {
    wrong = std::string(e.what()) + "; correct what follows --ros-args";
  } catch (const std::invalid_argument& e) {  // UsageError, and the generated nodes' parameter checks
    wrong = e.what();
  }
  std::fprintf(stderr, "%s: %s\n", program.c_str(), wrong.c_str());
  std::fflush(stderr);
  if (rclcpp::ok()) {
    rclcpp::shutdown();
  }
  return USAGE_STATUS;
}

}  // namespace rsaml_ros2
