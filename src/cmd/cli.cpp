// SPDX-License-Identifier: Apache-2.0
// The command line's shared conventions (see cli.h).
#include "cmd/cli.h"

#include <algorithm>
#include <filesystem>

#include "toroid/io/image_writer.h"     // image_format_of
#include "toroid/scene/scene_loader.h"  // edit_distance, shared with the scene's "did you mean"

namespace toroid::cmd {
namespace {

// "toroid" or "toroid render": how the user names `app`.
std::string command_name(const CLI::App* app) {
  std::string name = app->get_name();
  for (const CLI::App* p = app->get_parent(); p != nullptr; p = p->get_parent()) name = p->get_name() + " " + name;
  return name;
}

// "a", "a or b", "a, b or c".
std::string either(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i) s += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return s;
}

std::string mean(const std::string& s) { return " (did you mean '" + s + "'?)"; }

std::vector<std::string> subcommand_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands({}))
    if (!sub->get_name().empty()) names.push_back(sub->get_name());
  return names;
}

// An argument CLI11 left over that looks like an option: "-x", "--xyz",
// "--xyz=1", but not "--" nor a negative number.
bool looks_like_option(const std::string& arg) {
  return arg.size() > 1 && arg[0] == '-' && arg != "--" && !(arg[1] >= '0' && arg[1] <= '9') && arg[1] != '.';
}

std::string unknown_option(const CLI::App& app, const std::string& arg) {
  const std::string given = arg.substr(0, arg.find('='));
  std::vector<std::string> names;
  for (const CLI::Option* opt : app.get_options())
    for (const std::string& n : opt->get_lnames()) names.push_back(n);
  // Compared without their dashes: "-width" and "--widht" both mean --width.
  const std::size_t name_at = given.find_first_not_of('-');
  const std::string near = nearest(name_at == std::string::npos ? "" : given.substr(name_at), names);
  return "unknown option '" + given + "'" + (near.empty() ? "" : mean("--" + near));
}

bool is_scene_file(const std::string& arg) {
  const std::string ext = std::filesystem::path(arg).extension().string();
  return ext == ".yaml" || ext == ".yml";
}

std::string unknown_subcommand(const CLI::App& app, const std::string& arg) {
  const std::vector<std::string> names = subcommand_names(app);
  // `toroid scene.yaml`: the subcommand forgotten, not misspelt.
  if (is_scene_file(arg) && std::find(names.begin(), names.end(), "render") != names.end())
    return "unknown subcommand '" + arg + "'" + mean("toroid render " + arg);
  const std::string near = nearest(arg, names);
  return "unknown subcommand '" + arg + "'" + (near.empty() ? " (use " + either(names) + ")" : mean(near));
}

std::string unexpected_argument(const CLI::App& app, const std::string& arg) {
  // `toroid render scene.yaml out.png`: the image named without -o.
  const CLI::Option* output = app.get_option_no_throw("--output");
  if (image_format_of(arg) && output != nullptr && output->count() == 0)
    return "unexpected argument '" + arg + "'" + mean("-o " + arg);
  return "unexpected argument '" + arg + "'";
}

bool given(const CLI::Option* opt) { return opt != nullptr && opt->count() > 0; }

}  // namespace

std::string nearest(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  int best_d = 1 << 30;
  for (const std::string& c : candidates) {
    const int d = edit_distance(word, c);
    if (d < best_d) best_d = d, best = c;
  }
  // The scene loader's rule: 2 edits, or a third of the word if longer.
  const int limit = std::max<int>(2, static_cast<int>(word.size()) / 3);
  return best_d <= limit ? best : std::string{};
}

void add_version_flag(CLI::App& app) { app.set_version_flag("--version", kVersionLine); }

std::string usage_error(const CLI::App* top, const CLI::Error& e) {
  const std::vector<CLI::App*> parsed = top->get_subcommands();
  const CLI::App* sub = parsed.empty() ? nullptr : parsed.front();
  std::vector<const CLI::App*> apps{top};
  if (sub != nullptr) apps.push_back(sub);
  const CLI::App* where = sub != nullptr ? sub : top;
  std::string what;
  const std::vector<std::string> top_rest = top->remaining();
  if (sub == nullptr && !top_rest.empty() && !looks_like_option(top_rest[0])) {
    // No subcommand recognised: the words after this one were not parsed.
    what = unknown_subcommand(*top, top_rest[0]);
  } else {
    // What CLI11 did not recognise comes before its own message, which it
    // causes: in `render --widht 800 scene.yaml` the 800 became the scene.
    for (const CLI::App* app : apps)
      for (const std::string& arg : app->remaining())
        if (what.empty() && looks_like_option(arg)) what = unknown_option(*app, arg), where = app;
    for (const CLI::App* app : apps)
      for (const std::string& arg : app->remaining())
        if (what.empty() && arg != "--") what = unexpected_argument(*app, arg), where = app;
  }
  if (what.empty()) {
    what = e.what();
    if (sub == nullptr && dynamic_cast<const CLI::RequiredError*>(&e) != nullptr)
      what += " (use " + either(subcommand_names(*top)) + ")";
  }
  const std::string name = command_name(where);
  return name + ": " + what + "\nRun '" + name + " --help' for usage.\n";
}

int exit_on_parse_error(const CLI::App& app, const CLI::ParseError& e) {
  // CLI11 checks the options' values (a scene file that exists) before it
  // looks for --help, and stops at the first bad one; either flag given
  // anywhere wins.
  const std::vector<CLI::App*> parsed = app.get_subcommands();
  const CLI::App* sub = parsed.empty() ? nullptr : parsed.front();
  if (given(app.get_version_ptr()) || (sub != nullptr && given(sub->get_version_ptr())))
    return app.exit(CLI::CallForVersion(kVersionLine, 0));
  if (given(app.get_help_ptr()) || (sub != nullptr && given(sub->get_help_ptr()))) return app.exit(CLI::CallForHelp());
  // Every usage error exits 2, whatever CLI11's own code for it.
  return app.exit(e) == 0 ? 0 : 2;
}

}  // namespace toroid::cmd
