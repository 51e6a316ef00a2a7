// SPDX-License-Identifier: Apache-2.0
#pragma once

#include <CLI/CLI.hpp>

namespace toroid::cmd {

// Registers `toroid render SCENE -o OUT`; the callback runs it and sets `exit_code`.
void add_render_command(CLI::App& app, int& exit_code);

}  // namespace toroid::cmd
