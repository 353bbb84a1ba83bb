// convexloc-viewer — the web page's side of the platform: where the files the viewer writes
// go (the browser's downloads) and how the page hands it the user's files. On the desktop
// these do nothing.
#pragma once

namespace convexloc::viewer {

// Web page: makes the working directory an empty folder of the page's in-memory files,
// where the screenshots and SVGs are written. The desktop: nothing.
void preparePage();

// Web page: tells the page's script a frame was drawn (it counts them; the first one takes
// the loading note away). The desktop: nothing.
void frameDrawn();

// Web page: offers every PNG and SVG written into the working directory since the last call
// as a download, then deletes it. The desktop: nothing.
void offerDownloads();

}  // namespace convexloc::viewer

// The page's script calls this with a file it wrote into the in-memory files (the file
// picker's choice): the file opens at the next frame, as a dropped one does.
extern "C" void convexloc_open_file(const char* path);
