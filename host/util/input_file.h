// Input files opened for reading: regular files only, judged before a byte is read, so that a
// FIFO or a device can neither block raytex nor stream into it forever. Every reader of a file
// raytex did not make (scenes, includes, images, diff's inputs) opens it here. No Vulkan.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

// Opens `path` read-only: checked to be a regular file before the open (which does not block on
// a FIFO in any case) and again on what it opened. Returns the descriptor (blocking reads), or
// -1 with `*why` set to the reason ("No such file or directory", "not a regular file").
int openRegularFile(const std::string& path, std::string* why);

// openRegularFile as a stdio stream ("rb"), or null with `*why` set.
FILE* openRegularStream(const std::string& path, std::string* why);

enum class ReadStatus { Read, CannotOpen, TooLarge, ReadFailed };

// Reads the regular file `path` whole into `*text` when it holds at most `maxBytes` bytes:
// judged by its size before anything is read, and again while reading (a file that grows past
// maxBytes is refused, never cut short). `*why` explains CannotOpen and ReadFailed; `*size` is
// the file's size for TooLarge. Out of memory throws std::bad_alloc.
ReadStatus readWholeFile(const std::string& path, uint64_t maxBytes, std::string* text, std::string* why,
                         uint64_t* size);
