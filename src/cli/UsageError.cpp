#include "cli/UsageError.h"

#include <iostream>

#include <stdexcept>

#include "scene/DidYouMean.h"
#include "scene/SceneSchema.h"

namespace rollerdyn::cli {

namespace {

std::string joined(const std::vector<std::string>& words) {
  std::string s;
  for (std::size_t i = 0; i < words.size(); ++i) s += (i ? ", " : "") + words[i];
  return s;
}

std::vector<std::string> commandNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
  return names;
}

// Every spelling of the options of `cmd` ("--out", "-h", ...), for the did-you-mean.
std::vector<std::string> optionNames(const CLI::App& cmd) {
  std::vector<std::string> names;
  for (const CLI::Option* o : cmd.get_options()) {
    for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
    for (const std::string& s : o->get_snames()) names.push_back("-" + s);
  }
  return names;
}

// "unknown option '--outt' (did you mean '--out'?)" or "unexpected argument 'x'".
std::string extraArgument(const CLI::App& cmd, const std::string& arg) {
  if (arg.size() > 1 && arg[0] == '-') {
    const std::string name = arg.substr(0, arg.find('='));
    return "unknown option '" + name + "'" + didYouMean(name, optionNames(cmd));
  }
  return "unexpected argument '" + arg + "'";
}

std::string seeHelp(const std::string& command) {
  return "; see rollerdyn " + (command.empty() ? "" : command + " ") + "--help";
}

}  // namespace

std::string checkCommandWord(const CLI::App& app, int argc, const char* const* argv) {
  const std::vector<std::string> commands = commandNames(app);
  if (argc < 2) return "expected a command (" + joined(commands) + ")" + seeHelp("");
  const std::string first = argv[1];
  if (first == "-h" || first == "--help" || first == "--version") return "";
  for (const std::string& c : commands)
    if (first == c) return "";
  if (first.size() > 1 && first[0] == '-')
    return extraArgument(app, first) + "; expected a command first (" + joined(commands) + ")" + seeHelp("");
  return "unknown command '" + first + "'" + didYouMean(first, commands) + "; commands: " + joined(commands) +
         seeHelp("");
}

std::string usageMessage(CLI::App& app, const CLI::ParseError& error) {
  // The command being parsed when the error struck (CLI11 counts a subcommand once it is seen).
  CLI::App* cmd = nullptr;
  for (CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->count() > 0) cmd = sub;
  const std::string command = cmd ? cmd->get_name() : "";
  std::string what = error.what();
  // Arguments the command did not take are the likely cause of any error (a mistyped required
  // option also leaves that option missing), so they are reported first.
  const std::vector<std::string> extras = cmd ? cmd->remaining(false) : std::vector<std::string>{};
  if (!extras.empty()) {
    what.clear();
    for (const std::string& e : extras) what += (what.empty() ? "" : "; ") + extraArgument(*cmd, e);
  }
  return (command.empty() ? "" : command + ": ") + what + seeHelp(command);
}

int usageError(const std::string& message) {
  std::cerr << "rollerdyn: " << message << '\n';
  return kExitBadInput;
}

CLI::Validator oneOf(std::vector<std::string> choices) {
  const std::string list = joined(choices);
  return CLI::Validator(
      [choices, list](std::string& value) -> std::string {
        for (const std::string& c : choices)
          if (value == c) return "";
        return "expected one of " + list + ", got '" + value + "'" + didYouMean(value, choices);
      },
      "{" + list + "}", "one of " + list);
}

}  // namespace rollerdyn::cli
