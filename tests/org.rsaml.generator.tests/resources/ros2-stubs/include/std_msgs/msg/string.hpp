/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Stand-in for std_msgs/msg/String (see ../../../README.md).
#pragma once

#include <memory>
#include <string>

namespace std_msgs::msg {

struct String {
  using SharedPtr = std::shared_ptr<String>;
  using ConstSharedPtr = std::shared_ptr<const String>;
  std::string data{};
};

}  // namespace std_msgs::msg
