// SPDX-License-Identifier: Apache-2.0
// What `toroid` and each of its subcommands share: the version line, the help
// footer and the one-line usage errors with their suggestions.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "toroid/version.h"

namespace toroid::cmd {

inline constexpr char kVersionLine[] = "toroid " TOROID_VERSION_STRING;
inline constexpr char kRenderExample[] = "toroid render scenes/bagels.yaml -o bagels.png --width 800";
inline constexpr char kDocsLine[] = "Docs: README.md, and docs/scene-format.md for the scene format.";

// Gives `app` (toroid or a subcommand) its --version flag. Call it before
// adding options: CLI11 checks options in the order they were added, and
// --version must come before a positional's check (a scene file that exists).
void add_version_flag(CLI::App& app);

// The candidate nearest `word` if it is within a few edits (the scene
// loader's rule for its "did you mean"), else empty. On a tie the earliest
// candidate wins.
std::string nearest(const std::string& word, const std::vector<std::string>& candidates);

// For CLI::App::failure_message on the top-level app: "toroid SUB: what is
// wrong", naming an unknown subcommand or option (with a suggestion) in
// place of CLI11's message where one is to blame, then a line on --help.
std::string usage_error(const CLI::App* app, const CLI::Error& e);

// What main does with a parse error: --version and --help win over any other
// error on the command line, and print to stdout with status 0; anything else
// is a usage error, printed by usage_error, with status 2.
int exit_on_parse_error(const CLI::App& app, const CLI::ParseError& e);

}  // namespace toroid::cmd
