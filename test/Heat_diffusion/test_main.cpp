// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The main() of every test program: it runs the suite that its argument names (see
// test_support::run_suite and CMakeLists.txt).

#include "test_support.h"

int main(int argc, char** argv) { return test_support::run_suite(argc, argv); }
