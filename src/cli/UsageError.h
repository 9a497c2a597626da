// Usage errors of the `rollerdyn` command line, all reported the same way: exit code 2 and ONE
// line on stderr, "rollerdyn: <command>: <what is wrong> (did you mean '...'?); see
// rollerdyn <command> --help". The hints use the one edit distance of src/scene/DidYouMean.h for
// commands, options and choice values alike.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace rollerdyn::cli {

constexpr int kExitBadInput = 2;  // bad input or set-up (README: "Exit codes")

// Checks the command word before CLI11 parses (CLI11 would report an unknown command as "A
// subcommand is required"). Returns "" when argv names a command or only asks for --help or
// --version, else the one-line reason: no command, unknown command, unknown top-level option.
std::string checkCommandWord(const CLI::App& app, int argc, const char* const* argv);

// The one-line reason for a CLI11 parse error (not help or version), with the command it
// happened in and a did-you-mean for unknown options.
std::string usageMessage(CLI::App& app, const CLI::ParseError& error);

// Prints "rollerdyn: <message>" on stderr and returns kExitBadInput.
int usageError(const std::string& message);

// A validator accepting exactly one of `choices`; its message names them and the closest one,
// e.g. "expected one of multibody, reduced, got 'reducd' (did you mean 'reduced'?)".
CLI::Validator oneOf(std::vector<std::string> choices);

}  // namespace rollerdyn::cli
