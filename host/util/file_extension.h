// A file name's extension, the one rule by which raytex names formats: of its inputs (PNG,
// JPEG, EXR, PFM) and of its outputs (-o FILE).
#pragma once

#include <cctype>
#include <string>

// The text after the last dot of the path's last component, in lower case ("" without one):
// "a/b.PNG" -> "png", "a.b/c" -> "", ".exr" -> "exr".
inline std::string fileExtension(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}
