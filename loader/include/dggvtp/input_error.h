// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The loader's one exception: input that its input policy refuses.

#ifndef DGGVTP_INPUT_ERROR_H
#define DGGVTP_INPUT_ERROR_H

#include <stdexcept>

namespace dggvtp {

// Bad input: the message goes to the user as `error: <message>`, exit status 2.
struct Input_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

} // namespace dggvtp

#endif // DGGVTP_INPUT_ERROR_H
