#include "LiveView.h"

#include <dynslam/viz/AnnotatedFrame.h>
#include <dynslam/viz/MapScene.h>

#include <mrpt/gui/CDisplayWindow3D.h>
#include <mrpt/img/CImage.h>
#include <mrpt/opengl/CFBORender.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/stock_objects.h>
#include <mrpt/poses/CPose3D.h>
#include <opencv2/core.hpp>

#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <thread>

namespace dynslam::runner {
namespace {

constexpr const char* kImageViewport = "annotated_frame";
constexpr const char* kCurrentCamera = "current_camera";
/// The annotated frame's viewport: lower-left corner, this fraction of the window's width.
constexpr double kImageWidthFraction = 0.35;

/// The window's scene, locked for as long as this lives (the GUI thread draws it meanwhile).
class LockedScene {
 public:
  explicit LockedScene(mrpt::gui::CDisplayWindow3D& w) : w_(w), scene_(w.get3DSceneAndLock()) {}
  ~LockedScene() { w_.unlockAccess3DScene(); }
  mrpt::opengl::COpenGLScene& operator*() { return *scene_; }
  mrpt::opengl::COpenGLScene* operator->() { return scene_.get(); }

 private:
  mrpt::gui::CDisplayWindow3D& w_;
  mrpt::opengl::COpenGLScene::Ptr& scene_;
};

mrpt::poses::CPose3D toCPose3D(const Eigen::Isometry3d& T) {
  mrpt::math::CMatrixDouble44 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = T.matrix()(r, c);
  return mrpt::poses::CPose3D(m);
}

/// True when every pixel has the same value (a black read-back, an empty window).
bool singleColour(const mrpt::img::CImage& image) {
  if (image.isEmpty()) return true;
  cv::Scalar mean, stddev;
  cv::meanStdDev(image.asCvMatRef(), mean, stddev);
  for (int c = 0; c < 4; ++c)
    if (stddev[c] > 0) return false;
  return true;
}

}  // namespace

struct LiveView::Window {
  mrpt::gui::CDisplayWindow3D::Ptr window;
  bool camera_aimed = false;
};

std::string LiveView::displayProblem() {
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0')
    return "--gui needs an X display and $DISPLAY is not set; on a machine without one, run it "
           "under a virtual display: xvfb-run -a dynslam --gui ...";
  return "";
}

LiveView::LiveView(LiveViewOptions options)
    : window_(std::make_unique<Window>()), options_(options) {
  if (const auto problem = displayProblem(); !problem.empty()) throw std::runtime_error(problem);
  window_->window = mrpt::gui::CDisplayWindow3D::Create("dynslam: map, trajectory, objects",
                                                        static_cast<unsigned>(options_.width),
                                                        static_cast<unsigned>(options_.height));
  if (!window_->window || !window_->window->isOpen())
    throw std::runtime_error(std::string("--gui: cannot open a window on display '") +
                             std::getenv("DISPLAY") +
                             "' (is the X server running? without one: xvfb-run -a dynslam ...)");
  // The read-back costs one glReadPixels per redraw, at most max_rate_hz times a second.
  window_->window->captureImagesStart();
  window_->window->setCameraZoom(8.0f);
  window_->window->setCameraElevationDeg(35.0f);
}

LiveView::~LiveView() = default;

bool LiveView::isOpen() const { return window_->window && window_->window->isOpen(); }

void LiveView::update(const core::Frame& frame, const viz::MapSceneBuilder& map, bool force) {
  if (!isOpen()) {
    // Closed by the user: the run goes on headless, every output is still written.
    if (window_->window && !closed_reported_) {
      std::fprintf(stderr, "\ndynslam: the --gui window was closed; the run goes on without it\n");
      closed_reported_ = true;
    }
    return;
  }
  const auto now = std::chrono::steady_clock::now();
  if (!force && updates_ > 0 &&
      std::chrono::duration<double>(now - last_update_).count() < 1.0 / options_.max_rate_hz)
    return;
  last_update_ = now;
  ++updates_;

  // The map (static points, trajectory, tracks) is rebuilt from the voxels (a few ms at 50,000
  // points): refreshed at most every map_interval_s. The current camera and the annotated frame
  // follow at the full rate.
  std::optional<mrpt::opengl::COpenGLScene> fresh;
  if (force || updates_ == 1 ||
      std::chrono::duration<double>(now - last_map_update_).count() >= options_.map_interval_s) {
    last_map_update_ = now;
    fresh.emplace();
    map.fill(*fresh);
    auto camera = mrpt::opengl::stock_objects::CornerXYZSimple(0.25f, 3.0f);
    camera->setName(kCurrentCamera);
    camera->setVisibility(false);
    fresh->insert(camera);
  }
  const cv::Mat annotated = viz::renderAnnotatedFrame(frame);
  mrpt::img::CImage image(annotated, mrpt::img::DEEP_COPY);
  {
    LockedScene scene(*window_->window);
    if (fresh) {
      *scene = *fresh;
      auto viewport = scene->createViewport(kImageViewport);
      const double aspect = static_cast<double>(options_.width) / options_.height;
      const double h = kImageWidthFraction * aspect * annotated.rows / std::max(1, annotated.cols);
      viewport->setViewportPosition(0.0, 0.0, kImageWidthFraction, h);
      viewport->setBorderSize(1);
    }
    scene->getViewport(kImageViewport)->setImageView(std::move(image));
    if (auto camera = scene->getByName(kCurrentCamera); camera && frame.T_world_camera) {
      camera->setPose(toCPose3D(*frame.T_world_camera));
      camera->setVisibility(true);
    }
  }
  if (frame.T_world_camera && !window_->camera_aimed) {
    const Eigen::Vector3d p = frame.T_world_camera->translation();
    window_->window->setCameraPointingToPoint(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                              static_cast<float>(p.z()));
    window_->camera_aimed = true;
  }
  window_->window->forceRepaint();
  update_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - now).count();
}

std::string LiveView::saveScreenshot(const std::string& path) {
  auto& w = window_->window;
  if (!isOpen())
    throw std::runtime_error("--gui-screenshot: the window was closed before the run ended; " +
                             path + " not written");
  // A redraw after the last update, then the image it read back. The GUI thread draws
  // asynchronously and a redraw of an earlier update may still be on its way: take the second
  // new capture (waiting up to 5 s).
  auto previous = w->getLastWindowImagePtr();
  w->forceRepaint();
  mrpt::img::CImage::Ptr shot;
  int fresh = 0;
  for (int i = 0; i < 100 && fresh < 2; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    auto latest = w->getLastWindowImagePtr();
    if (latest && latest != previous) {
      shot = previous = latest;
      if (++fresh == 1) w->forceRepaint();
    }
  }
  std::string source = "window";
  mrpt::img::CImage image;
  if (shot && !singleColour(*shot)) {
    image = *shot;
  } else {
    // Mesa's llvmpipe under Xvfb reads the window back black: draw the same scene off-screen
    // from the window's viewpoint (the mouse may have moved it).
    source = "offscreen";
    mrpt::opengl::COpenGLScene scene;
    {
      LockedScene locked(*w);
      scene = *locked;
    }
    auto& camera = scene.getViewport()->getCamera();
    float x = 0, y = 0, z = 0;
    w->getCameraPointingToPoint(x, y, z);
    camera.setPointingAt(x, y, z);
    camera.setZoomDistance(w->getCameraZoom());
    camera.setAzimuthDegrees(w->getCameraAzimuthDeg());
    camera.setElevationDegrees(w->getCameraElevationDeg());
    mrpt::opengl::CFBORender renderer(static_cast<unsigned>(options_.width),
                                      static_cast<unsigned>(options_.height));
    renderer.render_RGB(scene, image);
  }
  if (singleColour(image))
    throw std::runtime_error("--gui-screenshot: the window's picture is blank; " + path +
                             " not written");
  if (!image.saveToFile(path))
    throw std::runtime_error("--gui-screenshot: cannot write '" + path + "'");
  return source;
}

}  // namespace dynslam::runner
