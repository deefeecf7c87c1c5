// The raytex command line: one table of options (cli.cpp) that parsing, --help and the
// reference in docs/cli.md all read. No Vulkan.
#pragma once

#include "benchmark.h"
#include "diff_report.h"
#include "render_options.h"

#include <string>
#include <vector>

enum class CliCommand { Help, Version, Render, View, Bench, Devices, Diff };

struct CliArgs {
  CliCommand command = CliCommand::Help;
  RenderOptions render;  // render, view and bench (bench writes -o only when given)
  BenchOptions bench;
  DiffOptions diff;
};

// Parses the arguments after the program name ("--name value" and "--name=value"). Throws
// UsageError with a one-line message: an unknown option, a bad value, an option the command
// does not take, or one that has no effect with the others given.
CliArgs parseCli(const std::vector<std::string>& args);

// `raytex --help`.
std::string usageText();

// The option table as Markdown: the reference section of docs/cli.md.
std::string optionReference();
