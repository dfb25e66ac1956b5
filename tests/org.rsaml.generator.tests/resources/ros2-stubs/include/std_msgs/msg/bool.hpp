/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Stand-in for std_msgs/msg/Bool (see ../../../README.md).
#pragma once

#include <memory>
#include <string>

namespace std_msgs::msg {

struct Bool {
  using SharedPtr = std::shared_ptr<Bool>;
  using ConstSharedPtr = std::shared_ptr<const Bool>;
  bool data{};
};

}  // namespace std_msgs::msg
