// convexloc-viewer — the web page's side of the platform: where the files the viewer writes
// go (the browser's downloads), how the page hands it the user's files, what the page's
// message box shows, and what the page's tests read of the view. On the desktop these do
// nothing, or what the command line does.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "logic/app/options.hpp"

namespace convexloc::viewer {

class Model;

// Web page: makes the working directory an empty folder of the page's in-memory files,
// where the screenshots and SVGs are written. The desktop: nothing.
void preparePage();

// The viewer's options. The desktop: the command line's, or its error. The web page: the
// URL's, where every option the viewer refuses is left out and its reason shown in the
// page's message box, so that the page always starts.
ParsedOptions parsePageOptions(std::span<const std::string_view> args);

// Web page: `text` in the page's message box (over the page, until closed). The desktop:
// on stderr.
void showPageProblem(const std::string& text);

// Web page: tells the page's script a frame was drawn (it counts them; the first one takes
// the loading note away), whether the pointer is over a panel, and the view's state for
// its tests and its swipes: the cameras, the left panel's scroll, the lecture's `slide`
// (from 0; -1 without a lecture) of its `slides`, whether a phone's drawer is open. The
// desktop: nothing.
void frameDrawn(const Model& model, std::ptrdiff_t slide, std::size_t slides);

// Web page: offers every PNG and SVG written into the working directory since the last call
// as a download, then deletes it. The desktop: nothing.
void offerDownloads();

}  // namespace convexloc::viewer

// The page's script calls this with a file it wrote into the in-memory files (the file
// picker's choice): the file opens at the next frame, as a dropped one does.
extern "C" void convexloc_open_file(const char* path);
