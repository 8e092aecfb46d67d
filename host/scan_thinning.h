#pragma once
// Thinning a 2D scan's beams, for training leg classifiers on legs farther away than the
// recordings hold (the `beam_steps` key of a training dataset).

#include "pedtrack/frame.h"

namespace pedtrack::cli {

/// The frame as a scanner with `step` times the angular spacing would see it: of every 2D scan
/// only beams offset, offset + step, offset + 2·step, ... are kept, each in its own direction.
/// A body at range r is then sampled as the full scan samples it at step·r: as many points,
/// as far apart in metres. Other observations are shared; the frame's clusters and labels are
/// not copied (the segmenters make them anew). step 1 copies the scans whole.
Frame thinnedFrame(const Frame& f, int step, int offset);

}  // namespace pedtrack::cli
