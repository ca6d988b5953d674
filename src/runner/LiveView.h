#pragma once
// --gui: a live MRPT 3-D window (mrpt::gui::CDisplayWindow3D) with what map.3Dscene will hold
// (static point map, camera trajectory, object tracks, from viz::MapSceneBuilder), the current
// camera, and the annotated picture of the frame (viz::renderAnnotatedFrame, as --frames writes
// it) in a viewport in the window's lower-left corner. MRPT-free header: the gui and opengl
// types stay in LiveView.cpp.
#include <dynslam/core/Frame.h>

#include <chrono>
#include <memory>
#include <string>

namespace dynslam::viz {
class MapSceneBuilder;
}

namespace dynslam::runner {

struct LiveViewOptions {
  /// The window is redrawn at most this often (the map goes through a scene copy each time,
  /// which costs milliseconds once it holds many points): frames in between are not shown.
  double max_rate_hz = 10.0;
  /// The map, trajectory and object tracks are refreshed at most this often (s); the current
  /// camera and the annotated frame at every redraw.
  double map_interval_s = 1.0;
  int width = 1024, height = 768;
};

class LiveView {
 public:
  /// Why a window cannot be opened here ("" when it can): no $DISPLAY.
  static std::string displayProblem();

  /// Opens the window; throws std::runtime_error when it cannot (no display, X refused).
  explicit LiveView(LiveViewOptions options = {});
  ~LiveView();

  /// Shows `frame` and `map` when the last redraw is older than 1 / max_rate_hz (or `force`).
  /// After the user closed the window this does nothing: the run goes on without it.
  void update(const core::Frame& frame, const viz::MapSceneBuilder& map, bool force = false);

  /// Writes the window's picture as it is now to `path` (PNG). The window's own capture is
  /// used; when that is blank (software GL under Xvfb can read back black), the same scene is
  /// rendered off-screen from the window's viewpoint instead. Returns which of the two was
  /// written ("window" or "offscreen"); throws std::runtime_error naming `path` on failure.
  std::string saveScreenshot(const std::string& path);

  bool isOpen() const;
  std::size_t updates() const { return updates_; }
  /// Time the redraws took on the calling (pipeline) thread, in total; the drawing itself
  /// happens on MRPT's GUI thread and is not in it.
  double updateSeconds() const { return update_s_; }

 private:
  struct Window;
  std::unique_ptr<Window> window_;
  LiveViewOptions options_;
  std::chrono::steady_clock::time_point last_update_{}, last_map_update_{};
  std::size_t updates_ = 0;
  double update_s_ = 0;
  bool closed_reported_ = false;
};

}  // namespace dynslam::runner
