#include "error.h"

std::string formatLoc(const FileLoc& loc, const std::string& message) {
  if (loc.line <= 0) return loc.file + ": " + message;  // about the whole file (cannot open it)
  return loc.file + ":" + std::to_string(loc.line) + ":" + std::to_string(loc.column) + ": " + message;
}

std::string errorLine(const Error& e) {
  if (e.located) return e.what();
  return std::string("raytex: ") + e.what();
}
