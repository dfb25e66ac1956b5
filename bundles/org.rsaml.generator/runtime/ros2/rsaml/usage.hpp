/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// How the runtime's programs (a node's executable, the container, the lifecycle manager) end on a
// wrong command-line argument or parameter: one line on stderr naming the program, the argument or
// parameter, what is wrong and how to fix it, and exit status 2, instead of std::terminate. Only
// those: an exception the nodes' own code lets escape (a std::invalid_argument of std::stoi among
// them) is that code's error, said as such in one line, and the program aborts as an uncaught
// exception makes any C++ program do, where it was thrown (a core dump shows where).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>
#include <typeinfo>

#if defined(__GNUG__)
#include <cxxabi.h>
#endif

#include <rclcpp/rclcpp.hpp>

namespace rsaml_ros2 {

/** Exit status of a program given a wrong argument or parameter (as a command-line usage error). */
constexpr int USAGE_STATUS = 2;

/**
 * A wrong argument or parameter of a runtime program or of a generated node, said with what is wrong
 * and how to fix it. The only std::invalid_argument run_main takes for a usage error.
 */
class UsageError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

namespace usage_detail {

/** The program's name, as run_main's lines say it. */
inline std::string& program() {
  static std::string name = "rsaml";
  return name;
}

/** What the program writes out before it aborts on an uncaught exception (init() sets it: the trace's queue); null: nothing. */
inline void (*&before_abort())() {
  static void (*write_out)() = nullptr;
  return write_out;
}

/** The type of an exception as the code names it (std::invalid_argument), where the compiler tells it. */
inline std::string type_name(const std::type_info& type) {
#if defined(__GNUG__)
  int status = 0;
  char* demangled = abi::__cxa_demangle(type.name(), nullptr, nullptr, &status);
  if (status == 0 && demangled != nullptr) {
    std::string name = demangled;
    std::free(demangled);
    return name;
  }
#endif
  return type.name();
}

/**
 * std::terminate's handler while run_main runs: an exception nothing caught (thrown by the nodes' code,
 * or a library it calls, on any thread) is said in one line with its type and what(), then the program
 * aborts. GCC and Clang do not unwind an exception no handler takes, so a core dump or a debugger still
 * shows where it was thrown.
 */
[[noreturn]] inline void say_uncaught() {
  std::string what = "std::terminate called without an exception";
  if (std::exception_ptr uncaught = std::current_exception()) {
    try {
      std::rethrow_exception(uncaught);
    } catch (const std::exception& e) {
      what = "uncaught " + type_name(typeid(e)) + ": " + e.what();
    } catch (...) {
#if defined(__GNUG__)
      const std::type_info* type = abi::__cxa_current_exception_type();
      what = "uncaught exception of type " + (type != nullptr ? type_name(*type) : std::string("unknown"));
#else
      what = "uncaught exception of a type that is not a std::exception";
#endif
    }
  }
  if (before_abort() != nullptr) {
    before_abort()();
  }
  std::fprintf(stderr, "%s: %s; an error in the node's code (or in a library it calls), not a wrong argument or parameter:"
               " the program aborts\n", program().c_str(), what.c_str());
  std::fflush(stderr);
  std::abort();
}

}  // namespace usage_detail

/**
 * Runs `body` (a program's main) and returns its status. A wrong argument or parameter ends it with
 * "PROGRAM: what is wrong" on stderr and USAGE_STATUS: a UsageError (the runtime's and the generated
 * nodes' checks of their arguments and parameters), and what rclcpp raises for a parameter of the wrong
 * type, an invalid value or QoS override (from a parameters file or -p), or an invalid argument after
 * --ros-args (a node name or namespace given there included). Any other exception, a std::invalid_argument
 * too, is not taken for one: see usage_detail::say_uncaught.
 */
template <typename BodyT>
int run_main(int argc, char** argv, BodyT body) {
  const char* slash = argc > 0 ? std::strrchr(argv[0], '/') : nullptr;
  if (argc > 0) {
    usage_detail::program() = slash != nullptr ? slash + 1 : argv[0];
  }
  std::set_terminate(usage_detail::say_uncaught);
  std::string wrong;
  try {
    return body();
  } catch (const UsageError& e) {
    wrong = e.what();
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
  }
  std::fprintf(stderr, "%s: %s\n", usage_detail::program().c_str(), wrong.c_str());
  std::fflush(stderr);
  if (rclcpp::ok()) {
    rclcpp::shutdown();
  }
  return USAGE_STATUS;
}

}  // namespace rsaml_ros2
