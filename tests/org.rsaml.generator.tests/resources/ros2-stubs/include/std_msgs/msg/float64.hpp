/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Stand-in for std_msgs/msg/Float64 (see ../../../README.md).
#pragma once

#include <memory>
#include <string>

namespace std_msgs::msg {

struct Float64 {
  using SharedPtr = std::shared_ptr<Float64>;
  using ConstSharedPtr = std::shared_ptr<const Float64>;
  double data{};
};

}  // namespace std_msgs::msg
