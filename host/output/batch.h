// Several scenes in one `raytex render` (one device): where each one's image goes. No Vulkan.
#pragma once

#include <string>
#include <vector>

struct BatchItem {
  std::string scene;
  std::string output;  // DIR/<scene's name without its extension>.<format's extension>
};

// Whether `output` names a directory for a batch's images: it ends in '/'.
bool isOutputDirectory(const std::string& output);

// The image each scene writes into `directory` (ending in '/'), with the extension `extension`
// (".png"). Throws UsageError or IoError when the directory is missing, not a directory or not
// writable, before anything renders. Two scenes writing one file, or an image replacing a file
// a scene reads, are the output plan's to refuse (headless.cpp, output_plan.h).
std::vector<BatchItem> planBatch(const std::vector<std::string>& scenes, const std::string& directory,
                                 const std::string& extension);
