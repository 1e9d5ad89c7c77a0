#include <strata/viewer/scene_panel.hpp>

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include <strata/date.hpp>
#include <strata/host/page_cache.hpp>
#include <strata/host/pipeline.hpp>

namespace strata::viewer {
namespace {

constexpr double kDaysEachWay = 366.0;  // a year either side: a seasonal series' whole cycle
constexpr double kHoursInADay = 24.0;

// The date a year either side of the pipeline's, and the time of day on its own slider: a day is too small a
// part of two years for one slider to set hours by, and the hours move the Earth's sun.
void drawDate(Engine& engine) {
  const std::optional<DayNumber>& given = engine.pipeline().date;
  std::optional<DayNumber>& date = engine.date();
  if (!given || !date) return;
  const double least = *given - kDaysEachWay, most = *given + kDaysEachWay;
  ImGui::SliderScalar("date", ImGuiDataType_Double, &*date, &least, &most, formatIsoDate(*date).c_str());
  const double day = std::floor(*date), midnight = 0.0;
  double hours = (*date - day) * kHoursInADay;
  if (ImGui::SliderScalar("time (UTC)", ImGuiDataType_Double, &hours, &midnight, &kHoursInADay, "%.2f h"))
    *date = std::clamp(day + hours / kHoursInADay, least, most);
}

// In a scene of several bodies: the body the camera is placed over, framed as the one before it was.
void drawCameraBody(Engine& engine) {
  const std::vector<SceneBody>& bodies = engine.pipeline().bodies;
  if (bodies.empty()) return;
  Camera& camera = engine.camera();
  if (!ImGui::BeginCombo("camera over", camera.body.c_str())) return;
  for (const SceneBody& body : bodies)
    if (ImGui::Selectable(body.id.c_str(), body.id == camera.body) && body.id != camera.body)
      camera = cameraOverBody(camera, engine.cameraBody(), body.pipeline.body, body.id);
  ImGui::EndCombo();
}

void drawStatistics(const Engine& engine) {
  const FrameStatistics& frame = engine.statistics();
  const GeometryStatistics geometry = engine.geometryStatistics();
  const PageCacheStatistics& pages = engine.pageCacheStatistics();
  ImGui::Text("frame %llu: prepare %.2f ms, render %.2f ms (CPU)", static_cast<unsigned long long>(frame.frame),
              frame.prepareMs, frame.renderMs);
  ImGui::Text("geometry: %d patches, %llu vertices, %llu triangles", geometry.patches,
              static_cast<unsigned long long>(geometry.vertices), static_cast<unsigned long long>(geometry.triangles));
  ImGui::Text("  visibility %.2f ms, subdivision %.2f ms, rasterisation %.2f ms", geometry.visibilityMs,
              geometry.subdivisionMs, geometry.rasterisationMs);
  ImGui::Text("pages: %d of %d resident, %d wanted, %d loading", pages.resident, pages.capacity, pages.wanted,
              pages.loading);
  ImGui::Text("  %llu uploaded, %llu evicted, %llu unreadable", static_cast<unsigned long long>(pages.uploaded),
              static_cast<unsigned long long>(pages.evicted), static_cast<unsigned long long>(pages.failed));
}

}  // namespace

Camera cameraOverBody(const Camera& camera, const Body& from, const Body& to, const std::string& id) {
  Camera over = camera;
  over.body = id;
  over.altitude = (camera.altitude + from.radius) / from.radius * to.radius - to.radius;
  return over;
}

void drawScenePanel(Engine& engine) {
  // Out of the way at first, folded at the top left: the frame is what a viewer opens to see.
  ImGui::SetNextWindowPos(ImVec2(0.0f, 24.0f), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
  ImGui::Begin("Scene");
  drawDate(engine);
  drawCameraBody(engine);
  drawStatistics(engine);
  ImGui::End();
}

}  // namespace strata::viewer
