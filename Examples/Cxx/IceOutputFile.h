// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// How ice-render and ice-bench write their files: never a partial file, never the user's old file
// lost to a failed or interrupted run, every write checked.
//
// A file is written whole to a temporary file in its own folder (".NAME.XXXXXX"), flushed to
// disk, then renamed over NAME: a reader sees the old file or the new one, nothing between. A
// symbolic link is followed (the link stays, its target is replaced). A path that names a device
// or a pipe (/dev/stdout, /dev/full) cannot be replaced: it is written directly, still checked.
#ifndef IceOutputFile_h
#define IceOutputFile_h

#include <string>

class vtkImageData;

namespace IceOutputFile
{
// Whether `path` can be written later, checked without creating or changing anything: its folder
// exists and is writable, it is not a folder itself. Returns "" or the problem in one sentence.
std::string CheckWritable(const std::string& path);

// Writes `data` to `path` as described above. Returns "" or the problem in one sentence (the
// old file, if any, is then unchanged and no temporary file is left).
std::string Write(const std::string& path, const std::string& data);

// The image format for `path`'s extension: "png" (.png) or "jpeg" (.jpg, .jpeg), else "".
std::string ImageFormat(const std::string& path);

// Encodes `image` as ImageFormat(path) in memory and writes it with Write().
std::string WriteImage(const std::string& path, vtkImageData* image);

// From now on SIGINT, SIGTERM, SIGHUP and SIGQUIT first remove the temporary file being written
// (if any), then end the program as the signal would have.
void RemoveTemporaryOnSignals();
}

#endif
