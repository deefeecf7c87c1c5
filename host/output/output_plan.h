// The output plan: every file a command will write and every file it reads, listed before any
// work and checked once, so that no output can destroy an input, another output, or land
// beside a device (docs/outputs.md, "The output plan"). render, a batch, --compare, diff
// --heatmap, bench -o and the viewer's F12 all build one. No Vulkan.
#pragma once

#include "scene.h"

#include <string>
#include <vector>

struct PlannedWrite {
  std::string path;
  std::string what;    // for messages: "the image", "the normal pass", "the heat map"
  bool named = true;   // named on the command line: an existing device or FIFO is written through
  std::string beside;  // a pass file: the image it is written beside, which must be a regular file
};

struct PlannedRead {
  std::string path;
  std::string what;  // for messages: "the scene file", "an image the scene uses"
  // Opened only after the check, which requires a regular file (diff's images, --compare's
  // reference). A scene's files were read already, and its images are checked by their loader.
  bool requireRegular = false;
};

struct OutputPlan {
  std::vector<PlannedWrite> writes;
  std::vector<PlannedRead> reads;
};

// Adds the scene's files (the scene, every file it includes) and the image of every material
// it defines to the plan's reads; `label` names the scene in the messages of its includes and
// images ("the scene", "the scene 'a.cfg'"; the scene file itself is "the scene file").
void planSceneReads(OutputPlan& plan, const Scene& scene, const std::string& label);

// Appends `more`'s writes and reads to `plan`.
void mergePlan(OutputPlan& plan, const OutputPlan& more);

// Checks the plan before anything is written, and throws at the first problem:
// - UsageError (exit 2), naming both paths: two writes are one file (the same path, or one file
//   through links or hard links), or a write is one file with a read (device and inode, after
//   symbolic links);
// - UsageError: a write not named on the command line (a pass file, a batch's image) that exists
//   and is not a regular file; a pass file beside an image that is a device or FIFO; a file name
//   longer than its directory allows (pathconf NAME_MAX), or a path of PATH_MAX bytes or more;
// - IoError (exit 1): a write into a directory that does not exist, or onto a directory;
// - ImageInputError (exit 2): a read with requireRegular that is missing or not a regular file.
// Standard output ("-") is no file and clashes with nothing.
void checkPlan(const OutputPlan& plan);

// The path a write creates or replaces: `path` with its symbolic links followed to the file they
// name, which may not exist yet (a link only the kernel can follow, such as /dev/stdout's, is
// kept as it is).
std::string writeTarget(const std::string& path);
