#include "map_view.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkLookupTable.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPointPicker.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <QLabel>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "axes_triad.h"
#include "colour_legend.h"
#include "colour_maps.h"
#include "common/angles.h"
#include "scale_bar.h"
#include "vtk_gl_widget.h"

namespace sonarcarve::widgets {
namespace {

vtkSmartPointer<vtkActor> makeActor(vtkPolyData* poly) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(poly);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

vtkSmartPointer<vtkLookupTable> lookupTable(const std::array<unsigned char, 3>* colours,
                                            int count) {
  auto lut = vtkSmartPointer<vtkLookupTable>::New();
  lut->SetNumberOfTableValues(count);
  for (int i = 0; i < count; ++i) {
    lut->SetTableValue(i, colours[i][0] / 255.0, colours[i][1] / 255.0, colours[i][2] / 255.0);
  }
  lut->Build();
  return lut;
}

// The points an actor's polydata draws; none when it is hidden.
std::vector<Eigen::Vector3d> drawnPointsOf(vtkActor* actor) {
  std::vector<Eigen::Vector3d> points;
  auto* poly = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInput());
  if (actor->GetVisibility() == 0 || poly == nullptr) {
    return points;
  }
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i) {
    double p[3];
    poly->GetPoint(i, p);
    points.emplace_back(p[0], p[1], p[2]);
  }
  return points;
}

}  // namespace

MapView::MapView(QWidget* parent) : QWidget(parent), gl_(new VtkGlWidget(this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(gl_);
  caption_ = new QLabel(this);
  caption_->setStyleSheet(
      "QLabel { color: #ffe9a8; background: rgba(20, 24, 30, 200); padding: 3px 6px; }");
  caption_->move(8, 8);
  caption_->hide();
  legend_ = new ColourLegend(this);
  legend_->hide();
  triad_ = new AxesTriad(this);
  scale_bar_ = new ScaleBar(this);
  connect(gl_, &VtkGlWidget::clicked, this, [this](QPoint position) {
    Eigen::Vector3d ned;
    const QString text = pickAt(position, &ned);
    if (!text.isEmpty()) {
      markPick(ned);
      emit pointPicked(text, QVector3D(static_cast<float>(ned.x()), static_cast<float>(ned.y()),
                                       static_cast<float>(ned.z())));
    }
  });
  // The mouse turns the camera without going through render(): follow it at every render.
  auto on_render = vtkSmartPointer<vtkCallbackCommand>::New();
  on_render->SetClientData(this);
  on_render->SetCallback([](vtkObject*, unsigned long, void* view, void*) {
    static_cast<MapView*>(view)->updateTriad();
  });
  vtkRenderer* renderer = gl_->renderer();
  renderer->AddObserver(vtkCommand::StartEvent, on_render);
  renderer->SetBackground(0.09, 0.11, 0.14);
  renderer->SetBackground2(0.22, 0.26, 0.31);
  renderer->GradientBackgroundOn();

  for (PointLayer* layer : {&map_layer_, &provisional_layer_, &surface_layer_}) {
    layer->poly = vtkSmartPointer<vtkPolyData>::New();
    layer->actor = makeActor(layer->poly);
    layer->actor->GetProperty()->SetPointSize(3.0f);
    renderer->AddActor(layer->actor);
  }
  surface_layer_.actor->GetProperty()->SetPointSize(4.0f);
  // Provisional voxels: see-through and smaller, so the settled map stands out.
  provisional_layer_.actor->GetProperty()->SetOpacity(0.3);
  provisional_layer_.actor->GetProperty()->SetPointSize(2.0f);

  track_actor_ = makeActor(vtkSmartPointer<vtkPolyData>::New());
  track_actor_->GetProperty()->SetColor(0.95, 0.85, 0.25);
  track_actor_->GetProperty()->SetLineWidth(2.0f);
  renderer->AddActor(track_actor_);

  frustum_actor_ = makeActor(vtkSmartPointer<vtkPolyData>::New());
  frustum_actor_->GetProperty()->SetColor(0.4, 0.85, 1.0);
  frustum_actor_->GetProperty()->SetRepresentationToWireframe();
  renderer->AddActor(frustum_actor_);

  fan_actor_ = makeActor(vtkSmartPointer<vtkPolyData>::New());
  fan_actor_->GetProperty()->LightingOff();
  renderer->AddActor(fan_actor_);

  // The picks: a marker at the last, a line from the one before; magenta, which neither colour
  // table uses.
  pick_marker_actor_ = makeActor(vtkSmartPointer<vtkPolyData>::New());
  pick_marker_actor_->GetProperty()->SetColor(1.0, 0.2, 0.85);
  pick_marker_actor_->GetProperty()->SetPointSize(12.0f);
  pick_marker_actor_->GetProperty()->RenderPointsAsSpheresOn();
  pick_marker_actor_->GetProperty()->LightingOff();
  renderer->AddActor(pick_marker_actor_);
  pick_line_actor_ = makeActor(vtkSmartPointer<vtkPolyData>::New());
  pick_line_actor_->GetProperty()->SetColor(1.0, 0.2, 0.85);
  pick_line_actor_->GetProperty()->SetLineWidth(3.0f);
  pick_line_actor_->GetProperty()->LightingOff();
  renderer->AddActor(pick_line_actor_);
  updatePickMarks();

  mesh_layer_.poly = vtkSmartPointer<vtkPolyData>::New();
  mesh_layer_.actor = makeActor(mesh_layer_.poly);
  renderer->AddActor(mesh_layer_.actor);
  setLayer(Layer::Map);

  redraw_timer_.setSingleShot(true);
  redraw_timer_.setInterval(kRedrawInterval_ms);
  connect(&redraw_timer_, &QTimer::timeout, this, &MapView::redraw);
  viewFromSide();
}

MapView::~MapView() {
  gl_->renderer()->RemoveObservers(vtkCommand::StartEvent);  // it would call back into this
}

void MapView::setCaption(const QString& text) {
  caption_->setText(text);
  caption_->adjustSize();
  caption_->setVisible(!text.isEmpty());
  caption_->raise();
}

QString MapView::caption() const {
  return caption_->text();
}

void MapView::clearMap() {
  const MapBlocks freed_here = takeMap();
}

MapView::MapBlocks MapView::takeMap() {
  MapBlocks taken = map_.take();
  latest_frames_done_ = 0;
  surface_ = MapViewBlock{};
  has_errors_ = false;
  first_points_ = true;
  mesh_ = MeshData{};
  fillMesh();
  setLayer(Layer::Map);
  redraw();
  return taken;
}

void MapView::setSurface(MapViewBlock surface) {
  surface_ = std::move(surface);
  has_errors_ = has_errors_ || !surface_.errors_m.empty();
  fillSurface();
  render();
}

MapView::PreparedResult MapView::prepareResult(MapViewBlock surface, MeshData mesh, ColourBy by,
                                               const ViewClip& clip) {
  PreparedResult prepared;
  prepared.colour_by = by;
  if (clip.active()) {
    prepared.region = clip.region();
  }
  const Eigen::AlignedBox3d* region = prepared.region ? &*prepared.region : nullptr;
  // As shownColouring(): error colouring only with errors to show.
  const bool errors = !surface.errors_m.empty() || !mesh.vertices.errors_m.empty();
  const ColourBy shown = by == ColourBy::Error && !errors ? ColourBy::Intensity : by;
  prepared.surface_layer = preparePoints({&surface}, region, 1, shown);
  prepared.mesh_layer = prepareMesh(mesh, region, shown);
  prepared.surface = std::move(surface);
  prepared.mesh = std::move(mesh);
  return prepared;
}

void MapView::setResult(PreparedResult result) {
  surface_ = std::move(result.surface);
  mesh_ = std::move(result.mesh);
  mesh_.vertices.values.resize(mesh_.vertices.points.size(), 0.0f);
  has_errors_ = has_errors_ || !surface_.errors_m.empty() || !mesh_.vertices.errors_m.empty();
  const Eigen::AlignedBox3d* region = clipRegion();
  const bool same_region =
      (region == nullptr && !result.region) ||
      (region != nullptr && result.region && region->min() == result.region->min() &&
       region->max() == result.region->max());
  if (same_region && result.colour_by == colour_by_ &&
      result.surface_layer.colours.by == shownColouring()) {
    adopt(surface_layer_, std::move(result.surface_layer));
    adopt(mesh_layer_, std::move(result.mesh_layer));
  } else {
    // The user changed the colouring or the clip while the run ended.
    fillSurface();
    fillMesh();
  }
  render();
}

void MapView::setLayer(Layer layer) {
  layer_ = layer;
  map_layer_.actor->SetVisibility(layer == Layer::Map);
  provisional_layer_.actor->SetVisibility(layer == Layer::Map);
  surface_layer_.actor->SetVisibility(layer == Layer::Surface);
  mesh_layer_.actor->SetVisibility(layer == Layer::Mesh);
  render();
}

std::vector<const MapViewBlock*> MapView::mapBlocks() const {
  std::vector<const MapViewBlock*> all;
  for (const auto& [id, b] : map_.blocks()) {
    all.push_back(&b);
  }
  return all;
}

bool MapView::provisional(const MapViewBlock& block) const {
  return live_ && latest_frames_done_ < block.frames_done + kSettleFrames;
}

void MapView::setLive(bool live) {
  live_ = live;
  scheduleRedraw();
}

std::size_t MapView::provisionalPointCount() const {
  return static_cast<std::size_t>(provisional_layer_.poly->GetNumberOfPoints());
}

std::size_t MapView::settledPointCount() const {
  return static_cast<std::size_t>(map_layer_.poly->GetNumberOfPoints());
}

void MapView::applyBlocks(std::vector<MapViewBlock> blocks) {
  for (const MapViewBlock& b : blocks) {
    if (!b.points.empty()) {
      has_errors_ = has_errors_ || !b.errors_m.empty();
      latest_frames_done_ = std::max(latest_frames_done_, b.frames_done);
    }
  }
  map_.apply(std::move(blocks));
  scheduleRedraw();
}

void MapView::setMapPointBudget(std::size_t max_points) {
  map_.setMaxPoints(max_points);
  scheduleRedraw();
}

void MapView::scheduleRedraw() {
  if (!redraw_timer_.isActive()) {
    redraw_timer_.start();
  }
}

void MapView::flush() {
  redraw_timer_.stop();
  redraw();
}

std::vector<Eigen::Vector3f> MapView::mapPoints() const {
  std::vector<Eigen::Vector3f> all;
  all.reserve(map_.pointCount());
  for (const auto& [id, b] : map_.blocks()) {
    all.insert(all.end(), b.points.begin(), b.points.end());
  }
  return all;
}

void MapView::fillMap() {
  // One stride for both parts, so that together they stay within kMaxDrawnMapPoints.
  std::vector<const MapViewBlock*> settled;
  std::vector<const MapViewBlock*> changing;
  std::size_t total = 0;
  for (const MapViewBlock* b : mapBlocks()) {
    (provisional(*b) ? changing : settled).push_back(b);
    total += voxelsInside({b}, clipRegion());
  }
  const std::size_t stride = strideFor(total, kMaxDrawnMapPoints);
  fillWithStride(map_layer_, settled, stride);
  fillWithStride(provisional_layer_, changing, stride);
  // One colour scale for both, from those that draw points (an empty one's scale is 0 to 1).
  const bool settled_drawn = map_layer_.poly->GetNumberOfPoints() > 0;
  const bool changing_drawn = provisional_layer_.poly->GetNumberOfPoints() > 0;
  const PointLayer& first = settled_drawn || !changing_drawn ? map_layer_ : provisional_layer_;
  const PointLayer& second = settled_drawn && changing_drawn ? provisional_layer_ : first;
  const double low = std::min(first.low, second.low);
  const double high = std::max(first.high, second.high);
  for (PointLayer* layer : {&map_layer_, &provisional_layer_}) {
    layer->low = low;
    layer->high = high;
    if (vtkMapper* mapper = layer->actor->GetMapper()) {
      mapper->SetScalarRange(low, high);
    }
  }
}

void MapView::redraw() {
  fillMap();
  if (first_points_ && !map_.blocks().empty()) {
    first_points_ = false;
    fitCamera();
  }
  render();
  emit redrawn(map_.pointCount());
}

void MapView::fillWithStride(PointLayer& layer, const std::vector<const MapViewBlock*>& blocks,
                             std::size_t stride) {
  adopt(layer, preparePoints(blocks, clipRegion(), stride, shownColouring()));
}

void MapView::fillSurface() {
  fillWithStride(surface_layer_, {&surface_}, 1);
  result_layers_built_here_ += surface_.points.empty() ? 0 : 1;
}

void MapView::fillMesh() {
  adopt(mesh_layer_, prepareMesh(mesh_, clipRegion(), shownColouring()));
  result_layers_built_here_ += mesh_.triangles.empty() ? 0 : 1;
}

void MapView::adopt(PointLayer& layer, PreparedLayer prepared) {
  layer.poly = std::move(prepared.poly);
  layer.stride = prepared.stride;
  vtkPolyDataMapper::SafeDownCast(layer.actor->GetMapper())->SetInputData(layer.poly);
  applyColours(layer, std::move(prepared.colours));
}

void MapView::applyColours(PointLayer& layer, LayerColours colours) {
  layer.poly->GetPointData()->SetScalars(colours.scalars);
  auto* mapper = vtkPolyDataMapper::SafeDownCast(layer.actor->GetMapper());
  const auto& table = colours.by == ColourBy::Error ? errorColours() : viridisColours();
  mapper->SetLookupTable(lookupTable(table.data(), static_cast<int>(table.size())));
  mapper->SetScalarRange(colours.low, colours.high);
  mapper->ScalarVisibilityOn();
  layer.coloured_by = colours.by;
  layer.low = colours.low;
  layer.high = colours.high;
}

MapView::ColourBy MapView::shownColouring() const {
  return colour_by_ == ColourBy::Error && !has_errors_ ? ColourBy::Intensity : colour_by_;
}

const Eigen::AlignedBox3d* MapView::clipRegion() const {
  return clip_.active() ? &clip_region_ : nullptr;
}

void MapView::setClip(const ViewClip& clip) {
  clip_ = clip;
  clip_region_ = clip.region();
  fillMap();
  fillSurface();
  fillMesh();
  render();
}

const MapView::PointLayer* MapView::shownLayer() const {
  switch (layer_) {
    case Layer::Map:
      return map_layer_.poly->GetNumberOfPoints() > 0 ? &map_layer_ : &provisional_layer_;
    case Layer::Surface:
      return &surface_layer_;
    case Layer::Mesh:
      break;
  }
  return &mesh_layer_;
}

std::size_t MapView::drawnPointCount() const {
  return drawnPoints().size();
}

std::vector<Eigen::Vector3f> MapView::drawnPoints() const {
  std::vector<const PointLayer*> shown{shownLayer()};
  if (layer_ == Layer::Map) {
    shown = {&map_layer_, &provisional_layer_};
  }
  std::vector<Eigen::Vector3f> points;
  for (const PointLayer* layer : shown) {
    for (vtkIdType i = 0; i < layer->poly->GetNumberOfPoints(); ++i) {
      double p[3];
      layer->poly->GetPoint(i, p);
      points.push_back(Eigen::Vector3d(p[0], p[1], p[2]).cast<float>());
    }
  }
  return points;
}

std::size_t MapView::drawnTriangleCount() const {
  return static_cast<std::size_t>(mesh_layer_.poly->GetNumberOfPolys());
}

Eigen::AlignedBox3d MapView::dataBounds() const {
  Eigen::AlignedBox3d bounds;
  for (const MapViewBlock* b : mapBlocks()) {
    for (const auto& p : b->points) {
      bounds.extend(p.cast<double>());
    }
  }
  for (const MapViewBlock* b : {&surface_, &mesh_.vertices}) {
    for (const auto& p : b->points) {
      bounds.extend(p.cast<double>());
    }
  }
  return bounds;
}

void MapView::recolour() {
  fillMap();
  applyColours(surface_layer_,
               layerColours({&surface_}, clipRegion(), surface_layer_.stride, shownColouring()));
  applyColours(mesh_layer_, layerColours({&mesh_.vertices}, nullptr, 1, shownColouring()));
}

void MapView::updateLegend() {
  const PointLayer* shown = shownLayer();
  if (shown->poly->GetNumberOfPoints() == 0) {
    legend_->hide();
    return;
  }
  switch (shown->coloured_by) {
    case ColourBy::Depth:
      legend_->setScale(tr("depth (m)"), shown->low, shown->high, viridisColours());
      break;
    case ColourBy::Error:
      legend_->setScale(tr("error vs ground truth (cm)"), 100.0 * shown->low, 100.0 * shown->high,
                        errorColours());
      break;
    case ColourBy::Intensity:
      legend_->setScale(tr("intensity (%1)").arg(intensity_unit_), shown->low, shown->high,
                        viridisColours());
      break;
  }
  legend_->move(8, height() - legend_->height() - 8);
  legend_->show();  // over the GL view, made before it
}

void MapView::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  updateLegend();
  updateTriad();
}

void MapView::updateTriad() {
  vtkMatrix4x4* view = gl_->renderer()->GetActiveCamera()->GetViewTransformMatrix();
  std::array<QPointF, 3> axes;
  for (int axis = 0; axis < 3; ++axis) {
    // The world axis in the camera's frame (x right, y up): its screen direction, y down.
    axes[static_cast<std::size_t>(axis)] =
        QPointF(view->GetElement(0, axis), -view->GetElement(1, axis));
  }
  triad_->setAxes(axes);
  triad_->move(width() - triad_->width() - 4, height() - triad_->height() - 4);
  updateScaleBar();
}

void MapView::updateScaleBar() {
  vtkCamera* camera = gl_->renderer()->GetActiveCamera();
  // The height of the view at the focal point, in metres: VTK's view angle is vertical.
  const double view_height_m =
      camera->GetParallelProjection() != 0
          ? 2.0 * camera->GetParallelScale()
          : 2.0 * camera->GetDistance() * std::tan(degToRad(camera->GetViewAngle()) / 2.0);
  scale_bar_->setMetresPerPixel(gl_->height() > 0 ? view_height_m / gl_->height() : 0.0);
  // Over the triad, clear of the colour key on the left.
  scale_bar_->move(width() - scale_bar_->width() - 4,
                   height() - triad_->height() - scale_bar_->height() - 8);
}

QString MapView::pickAt(QPoint position, Eigen::Vector3d* ned) {
  const PointLayer* shown = layer_ == Layer::Map       ? &map_layer_
                            : layer_ == Layer::Surface ? &surface_layer_
                                                       : nullptr;
  if (shown == nullptr || shown->poly->GetNumberOfPoints() == 0) {
    return {};
  }
  // The pick ray runs between the camera's clipping planes, which a render resets after the
  // camera moves: reset them here, or a pick made before the next render (a click while the
  // machine is busy) finds another point of the same column than the one after it.
  gl_->renderer()->ResetCameraClippingRange();
  auto picker = vtkSmartPointer<vtkPointPicker>::New();
  picker->SetTolerance(0.005);  // of the window's diagonal
  picker->PickFromListOn();
  picker->AddPickList(shown->actor);
  const double ratio = gl_->devicePixelRatioF();
  const double x = position.x() * ratio;
  const double y = (gl_->height() - 1 - position.y()) * ratio;
  if (picker->Pick(x, y, 0.0, gl_->renderer()) == 0 || picker->GetPointId() < 0) {
    return {};
  }
  const vtkIdType id = picker->GetPointId();
  double p[3];
  shown->poly->GetPoint(id, p);
  if (ned != nullptr) {
    *ned = Eigen::Vector3d(p[0], p[1], p[2]);
  }
  const double value = shown->poly->GetPointData()->GetScalars()->GetComponent(id, 0);
  QString what;
  switch (shown->coloured_by) {
    case ColourBy::Depth:
      what = tr("depth %1 m").arg(value, 0, 'f', 2);
      break;
    case ColourBy::Error:
      what = tr("error %1 cm").arg(100.0 * value, 0, 'f', 1);
      break;
    case ColourBy::Intensity:
      what = tr("intensity %1 %2").arg(value, 0, 'f', 0).arg(intensity_unit_);
      break;
  }
  // A point held at a coarser level of detail: the centroid and the mean of its voxels.
  if (vtkDataArray* voxels = shown->poly->GetPointData()->GetArray(kVoxelsArray)) {
    const auto count = static_cast<int>(voxels->GetComponent(id, 0));
    if (count > 1) {
      what += tr(" (mean of %1 voxels)").arg(count);
    }
  }
  return tr("N %1 E %2 D %3 m, %4")
      .arg(p[0], 0, 'f', 2)
      .arg(p[1], 0, 'f', 2)
      .arg(p[2], 0, 'f', 2)
      .arg(what);
}

void MapView::markPick(const Eigen::Vector3d& ned) {
  picks_.push_back(ned);
  if (picks_.size() > 2) {
    picks_.erase(picks_.begin());
  }
  updatePickMarks();
  render();
}

void MapView::clearPicks() {
  picks_.clear();
  updatePickMarks();
  render();
}

void MapView::updatePickMarks() {
  const auto polyline = [](const std::vector<Eigen::Vector3d>& at) {
    auto points = vtkSmartPointer<vtkPoints>::New();
    for (const Eigen::Vector3d& p : at) {
      points->InsertNextPoint(p.data());
    }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    const auto n = static_cast<vtkIdType>(at.size());
    if (n == 1) {
      poly->SetVerts(pointCells(n, false));
    } else if (n > 1) {
      poly->SetLines(pointCells(n, true));
    }
    return poly;
  };
  const std::vector<Eigen::Vector3d> last(picks_.empty() ? picks_.end() : picks_.end() - 1,
                                          picks_.end());
  vtkPolyDataMapper::SafeDownCast(pick_marker_actor_->GetMapper())->SetInputData(polyline(last));
  pick_marker_actor_->SetVisibility(!picks_.empty());
  vtkPolyDataMapper::SafeDownCast(pick_line_actor_->GetMapper())->SetInputData(polyline(picks_));
  pick_line_actor_->SetVisibility(picks_.size() == 2);
}

std::vector<Eigen::Vector3d> MapView::pickMarkerPoints() const {
  return drawnPointsOf(pick_marker_actor_);
}

std::vector<Eigen::Vector3d> MapView::pickLinePoints() const {
  return drawnPointsOf(pick_line_actor_);
}

QPoint MapView::screenPositionOf(const Eigen::Vector3d& ned) const {
  vtkRenderer* renderer = gl_->renderer();
  renderer->SetWorldPoint(ned.x(), ned.y(), ned.z(), 1.0);
  renderer->WorldToDisplay();
  double d[3];
  renderer->GetDisplayPoint(d);
  const double ratio = gl_->devicePixelRatioF();
  return {static_cast<int>(std::lround(d[0] / ratio)),
          static_cast<int>(std::lround(gl_->height() - 1 - d[1] / ratio))};
}

std::array<QPointF, 3> MapView::axesOnScreen() const {
  return triad_->axes();
}

QString MapView::legendText() const {
  return legend_->isVisibleTo(this) ? legend_->text() : QString();
}

const char* MapView::nameOf(ColourBy by) {
  switch (by) {
    case ColourBy::Depth:
      return "depth";
    case ColourBy::Error:
      return "error";
    case ColourBy::Intensity:
      break;
  }
  return "intensity";
}

MapView::ColourBy MapView::colourByNamed(std::string_view name) {
  for (ColourBy by : {ColourBy::Depth, ColourBy::Error}) {
    if (name == nameOf(by)) {
      return by;
    }
  }
  return ColourBy::Intensity;
}

void MapView::setColourBy(ColourBy by) {
  colour_by_ = by;
  recolour();
  render();
}

void MapView::setTrack(const std::vector<Eigen::Vector3d>& positions_m) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  for (const auto& p : positions_m) {
    points->InsertNextPoint(p.x(), p.y(), p.z());
  }
  poly->SetPoints(points);
  poly->SetLines(pointCells(static_cast<vtkIdType>(positions_m.size()), true));
  vtkPolyDataMapper::SafeDownCast(track_actor_->GetMapper())->SetInputData(poly);
  render();
}

void MapView::setIntensityUnit(const QString& unit) {
  intensity_unit_ = unit;
  updateLegend();
}

void MapView::setCurrentFrame(const Eigen::Isometry3d& T_world_sonar, const SonarModel& sonar,
                              const cv::Mat& image) {
  const double r0 = sonar.range().min_m;
  const double r1 = sonar.range().maxRange();
  const double b0 = sonar.bearings().leftEdge();
  const double b1 = sonar.bearings().rightEdge();
  const double half_elev = sonar.verticalAperture() / 2.0;
  const auto world = [&](double r, double b, double e) {
    const Eigen::Vector3d p = T_world_sonar * pointFromPolar({r, b, e});
    return p;
  };
  // Frustum: the far surface's outline and the edges from the sonar to its corners.
  {
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    const Eigen::Vector3d origin = T_world_sonar.translation();
    const vtkIdType o = points->InsertNextPoint(origin.data());
    constexpr int kArc = 24;
    for (double e : {-half_elev, half_elev}) {
      std::vector<vtkIdType> arc;
      for (int k = 0; k <= kArc; ++k) {
        const double b = b0 + (b1 - b0) * k / kArc;
        arc.push_back(points->InsertNextPoint(world(r1, b, e).data()));
      }
      lines->InsertNextCell(static_cast<vtkIdType>(arc.size()), arc.data());
      const vtkIdType edge_a[2] = {o, arc.front()};
      const vtkIdType edge_b[2] = {o, arc.back()};
      lines->InsertNextCell(2, edge_a);
      lines->InsertNextCell(2, edge_b);
    }
    for (double b : {b0, b1}) {
      const vtkIdType side[2] = {points->InsertNextPoint(world(r1, b, -half_elev).data()),
                                 points->InsertNextPoint(world(r1, b, half_elev).data())};
      lines->InsertNextCell(2, side);
    }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetLines(lines);
    vtkPolyDataMapper::SafeDownCast(frustum_actor_->GetMapper())->SetInputData(poly);
  }
  // Fan: the polar image on the elevation-0 plane, at most 96 x 96 cells.
  if (!image.empty()) {
    const int nb = std::min(96, image.cols);
    const int nr = std::min(96, image.rows);
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colours->SetNumberOfComponents(4);
    double max_value = 1.0;
    cv::minMaxLoc(image, nullptr, &max_value);
    const auto& map = copperColours();
    for (int ir = 0; ir <= nr; ++ir) {
      const double r = r0 + (r1 - r0) * ir / nr;
      const int row = sonar.range().binOf(r).value_or(image.rows - 1);
      for (int ib = 0; ib <= nb; ++ib) {
        const double b = b0 + (b1 - b0) * ib / nb;
        const int col = sonar.bearings().beamOf(b).value_or(ib == 0 ? 0 : image.cols - 1);
        points->InsertNextPoint(world(r, b, 0.0).data());
        const double v = image.at<float>(row, col) / std::max(1e-6, max_value);
        const auto& c = map[static_cast<std::size_t>(std::clamp(v, 0.0, 1.0) * (map.size() - 1))];
        // Empty water is see-through, so the fan does not hide the map behind it.
        const unsigned char rgba[4] = {c[0], c[1], c[2],
                                       static_cast<unsigned char>(v > 0.02 ? 230 : 25)};
        colours->InsertNextTypedTuple(rgba);
      }
    }
    auto quads = vtkSmartPointer<vtkCellArray>::New();
    for (int ir = 0; ir < nr; ++ir) {
      for (int ib = 0; ib < nb; ++ib) {
        const vtkIdType a = ir * (nb + 1) + ib;
        const vtkIdType q[4] = {a, a + 1, a + nb + 2, a + nb + 1};
        quads->InsertNextCell(4, q);
      }
    }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetPolys(quads);
    poly->GetPointData()->SetScalars(colours);
    auto* mapper = vtkPolyDataMapper::SafeDownCast(fan_actor_->GetMapper());
    mapper->SetInputData(poly);
    mapper->SetColorModeToDirectScalars();
  }
  render();
}

void MapView::setMesh(const Mesh& mesh, std::vector<float> vertex_errors_m) {
  mesh_ = meshData(mesh, std::move(vertex_errors_m));
  has_errors_ = has_errors_ || !mesh_.vertices.errors_m.empty();
  fillMesh();
  render();
}

void MapView::fitCamera() {
  // Fit what the analyst is looking at: the shown points, else everything.
  vtkPolyData* poly = shownLayer()->poly;
  if (poly != nullptr && poly->GetNumberOfPoints() > 0) {
    gl_->renderer()->ResetCamera(poly->GetBounds());
  } else {
    gl_->renderer()->ResetCamera();
  }
  gl_->renderer()->ResetCameraClippingRange();
  render();
}

void MapView::viewFromTop() {
  vtkCamera* camera = gl_->renderer()->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(0, 0, -1);  // above (NED: up is -z), looking down
  camera->SetViewUp(1, 0, 0);     // north up, east to the right
  fitCamera();
}

void MapView::viewFromSide() {
  vtkCamera* camera = gl_->renderer()->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(-1, 0, 0);  // from the south, looking north
  camera->SetViewUp(0, 0, -1);    // up is -down, east to the right
  fitCamera();
}

void MapView::setOrthographic(bool on) {
  gl_->renderer()->GetActiveCamera()->SetParallelProjection(on);
  fitCamera();
}

bool MapView::orthographic() const {
  return gl_->renderer()->GetActiveCamera()->GetParallelProjection() != 0;
}

CameraState MapView::cameraState() const {
  vtkCamera* camera = gl_->renderer()->GetActiveCamera();
  CameraState s;
  camera->GetPosition(s.position.data());
  camera->GetFocalPoint(s.focal_point.data());
  camera->GetViewUp(s.view_up.data());
  s.parallel = camera->GetParallelProjection() != 0;
  s.parallel_scale = camera->GetParallelScale();
  s.view_angle_deg = camera->GetViewAngle();
  return s;
}

void MapView::setCameraState(const CameraState& s) {
  vtkCamera* camera = gl_->renderer()->GetActiveCamera();
  camera->SetPosition(s.position.data());
  camera->SetFocalPoint(s.focal_point.data());
  camera->SetViewUp(s.view_up.data());
  camera->SetParallelProjection(s.parallel);
  camera->SetParallelScale(s.parallel_scale);
  camera->SetViewAngle(s.view_angle_deg);
  first_points_ = false;  // a restored view is kept when points arrive
  gl_->renderer()->ResetCameraClippingRange();
  render();
}

QImage MapView::grabImage() {
  gl_->renderer()->ResetCameraClippingRange();
  return gl_->grabFramebuffer();
}

void MapView::render() {
  updateLegend();
  updateTriad();
  gl_->renderer()->ResetCameraClippingRange();
  gl_->requestRender();
}

}  // namespace sonarcarve::widgets
