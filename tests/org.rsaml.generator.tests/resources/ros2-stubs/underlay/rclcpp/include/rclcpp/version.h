/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Stand-in for rclcpp/version.h: the version of rclcpp the stand-in mirrors (Jazzy's).
#pragma once

#define RCLCPP_VERSION_MAJOR (28)
#define RCLCPP_VERSION_MINOR (1)
#define RCLCPP_VERSION_PATCH (6)
#define RCLCPP_VERSION_GTE(major, minor, patch) \
  ((major) < RCLCPP_VERSION_MAJOR ? true        \
   : (major) > RCLCPP_VERSION_MAJOR ? false     \
   : (minor) < RCLCPP_VERSION_MINOR ? true      \
   : (minor) > RCLCPP_VERSION_MINOR ? false     \
   : (patch) <= RCLCPP_VERSION_PATCH)
