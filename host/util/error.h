// Every failure raytex reports: one type per kind of failure, each carrying the one line the
// user sees. main() maps the kind to the exit code (main.cpp, exitCode); nothing else chooses
// an exit code. No Vulkan.
#pragma once

#include <stdexcept>
#include <string>

enum class ErrorKind {
  Usage,        // the command line, or an output raytex may not write
  Scene,        // a scene file: file:line:col
  ImageInput,   // an image file a scene names, refused or undecodable
  Device,       // Vulkan, or a limit of the device (an image it cannot hold included)
  OutOfMemory,  // host memory
  Io,           // an output file or standard output not written
  Internal,     // anything else: a bug
};

struct FileLoc {
  std::string file;
  int line = 0;    // 1-based
  int column = 0;  // 1-based
};

// "file:line:col: message", the form every error about a scene's content takes.
std::string formatLoc(const FileLoc& loc, const std::string& message);

struct Error : std::runtime_error {
  ErrorKind kind;
  bool located = false;  // the message starts with loc: file:line:col
  FileLoc loc;
  Error(ErrorKind k, const std::string& message) : std::runtime_error(message), kind(k) {}
  Error(ErrorKind k, const FileLoc& where, const std::string& message)
      : std::runtime_error(formatLoc(where, message)), kind(k), located(true), loc(where) {}
};

struct UsageError : Error {
  explicit UsageError(const std::string& message) : Error(ErrorKind::Usage, message) {}
};

struct SceneError : Error {
  SceneError(const FileLoc& where, const std::string& message) : Error(ErrorKind::Scene, where, message) {}
};

// An image file refused or undecodable; at the texture's location when a scene names it.
struct ImageInputError : Error {
  explicit ImageInputError(const std::string& message) : Error(ErrorKind::ImageInput, message) {}
  ImageInputError(const FileLoc& where, const std::string& message) : Error(ErrorKind::ImageInput, where, message) {}
};

// A Vulkan call failed, or the device cannot do what the render needs.
struct VulkanError : Error {
  explicit VulkanError(const std::string& message) : Error(ErrorKind::Device, message) {}
};

struct IoError : Error {
  explicit IoError(const std::string& message) : Error(ErrorKind::Io, message) {}
};

// The line printed on stderr for `e`: a located error as it is (it starts with its file), any
// other behind "raytex: ".
std::string errorLine(const Error& e);
