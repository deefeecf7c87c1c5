// raytex: texture-mapping ray tracer on Vulkan compute. Commands and options: cli.cpp.
#include "cli.h"
#include "benchmark.h"
#include "device.h"
#include "diff_report.h"
#include "error.h"
#include "atomic_file.h"
#include "render_command.h"
#include "render_files.h"
#include "viewer.h"

#include <cstdio>
#include <new>
#include <system_error>

#include <unistd.h>

namespace {

// The exit code of each kind of failure: the one mapping, which --help, docs/cli.md and the
// README list.
int exitCode(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::Usage: return 2;
    case ErrorKind::Scene: return 2;
    case ErrorKind::ImageInput: return 2;
    case ErrorKind::Device: return 1;
    case ErrorKind::OutOfMemory: return 1;
    case ErrorKind::Io: return 1;
    case ErrorKind::Internal: return 1;
  }
  return 1;
}

// raytex diff answers as cmp does: 1 is a --fail-* limit exceeded, so every failure is 2.
int failureCode(ErrorKind kind, bool diff) { return diff ? 2 : exitCode(kind); }

// The command's exit code when it does not throw (diff: 1 when over a limit).
int runCommand(const CliArgs& cli) {
  switch (cli.command) {
    case CliCommand::Help: fputs(usageText().c_str(), stdout); break;
    case CliCommand::Version: puts(kRaytexVersion); break;
    case CliCommand::Devices: fputs(listDevices().c_str(), stdout); break;
    case CliCommand::Render: return runRenderCommand(cli.render, cli.diff);
    case CliCommand::View: runViewer(cli.render); break;
    case CliCommand::Bench: runBench(cli.render, cli.bench); break;
    case CliCommand::Diff: return runDiff(cli.diff);
  }
  return 0;
}

// One line on stderr and `code`.
int fail(const std::string& line, int code) {
  fprintf(stderr, "%s\n", line.c_str());
  return code;
}

}  // namespace

// Every failure ends here: one line on stderr and the exit code of its kind (exitCode).
int main(int argc, char** argv) {
  // Output to a file or pipe is held until finishStdout (up to 64 KiB: --help, --json, the
  // device list), so a failed write is seen there with its errno; a terminal stays line-buffered.
  static char stdoutBuffer[1 << 16];  // glibc ignores the size of a buffer it allocates itself
  if (!isatty(fileno(stdout))) setvbuf(stdout, stdoutBuffer, _IOFBF, sizeof stdoutBuffer);
  const bool diff = argc > 1 && std::string(argv[1]) == "diff";
  try {
    const int code = runCommand(parseCli(std::vector<std::string>(argv + 1, argv + argc)));
    finishStdout(stdout);
    return code;
  } catch (const Error& e) {
    return fail(errorLine(e), failureCode(e.kind, diff));
  } catch (const std::bad_alloc&) {
    return fail("raytex: out of memory", failureCode(ErrorKind::OutOfMemory, diff));
  } catch (const std::system_error& e) {
    // A thread that cannot start for want of memory (EAGAIN), in raytex or in a Vulkan layer.
    if (e.code() == std::errc::resource_unavailable_try_again || e.code() == std::errc::not_enough_memory)
      return fail("raytex: out of memory: " + std::string(e.what()), failureCode(ErrorKind::OutOfMemory, diff));
    return fail(std::string("raytex: internal error: ") + e.what(), failureCode(ErrorKind::Internal, diff));
  } catch (const std::exception& e) {
    return fail(std::string("raytex: internal error: ") + e.what(), failureCode(ErrorKind::Internal, diff));
  } catch (...) {
    return fail("raytex: internal error: an unknown exception", failureCode(ErrorKind::Internal, diff));
  }
}
