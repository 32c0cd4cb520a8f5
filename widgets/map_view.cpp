#include "map_view.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
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
#include <limits>

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

// Cells that draw each point, or consecutive points as one polyline.
vtkSmartPointer<vtkCellArray> pointCells(vtkIdType count, bool as_line) {
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  connectivity->SetNumberOfValues(count);
  for (vtkIdType i = 0; i < count; ++i) {
    connectivity->SetValue(i, i);
  }
  if (as_line) {
    offsets->SetNumberOfValues(count > 0 ? 2 : 1);
    offsets->SetValue(0, 0);
    if (count > 0) {
      offsets->SetValue(1, count);
    }
  } else {
    offsets->SetNumberOfValues(count + 1);
    for (vtkIdType i = 0; i <= count; ++i) {
      offsets->SetValue(i, i);
    }
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  return cells;
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

// Calls visit(block, k) for each point drawn: those inside `region` (all without one), every
// stride-th of them.
template <typename Visit>
void forEachDrawn(const std::vector<const MapViewBlock*>& blocks, const Eigen::AlignedBox3d* region,
                  std::size_t stride, Visit visit) {
  std::size_t seen = 0;
  for (const MapViewBlock* b : blocks) {
    for (std::size_t k = 0; k < b->points.size(); ++k) {
      if (region != nullptr && !region->contains(b->points[k].cast<double>())) {
        continue;
      }
      if (seen++ % stride == 0) {
        visit(*b, k);
      }
    }
  }
}

// How many points of `blocks` lie inside `region` (all without one).
std::size_t countInside(const std::vector<const MapViewBlock*>& blocks,
                        const Eigen::AlignedBox3d* region) {
  std::size_t n = 0;
  if (region == nullptr) {
    for (const MapViewBlock* b : blocks) {
      n += b->points.size();
    }
    return n;
  }
  forEachDrawn(blocks, region, 1, [&](const MapViewBlock&, std::size_t) { ++n; });
  return n;
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
  blocks_.clear();
  latest_frames_done_ = 0;
  surface_ = MapViewBlock{};
  has_errors_ = false;
  first_points_ = true;
  setMesh(Mesh{});
  setLayer(Layer::Map);
  redraw();
}

void MapView::setSurface(MapViewBlock surface) {
  surface_ = std::move(surface);
  fill(surface_layer_, {&surface_}, std::numeric_limits<std::size_t>::max());
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
  for (const auto& [id, b] : blocks_) {
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
  for (MapViewBlock& b : blocks) {
    if (b.points.empty()) {
      blocks_.erase(b.block);
    } else {
      has_errors_ = has_errors_ || !b.errors_m.empty();
      latest_frames_done_ = std::max(latest_frames_done_, b.frames_done);
      blocks_[b.block] = std::move(b);
    }
  }
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

std::size_t MapView::mapPointCount() const {
  std::size_t n = 0;
  for (const auto& [id, b] : blocks_) {
    n += b.points.size();
  }
  return n;
}

std::vector<Eigen::Vector3f> MapView::mapPoints() const {
  std::vector<Eigen::Vector3f> all;
  all.reserve(mapPointCount());
  for (const auto& [id, b] : blocks_) {
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
    total += countInside({b}, clipRegion());
  }
  const std::size_t stride =
      total <= kMaxDrawnMapPoints ? 1 : (total + kMaxDrawnMapPoints - 1) / kMaxDrawnMapPoints;
  fillWithStride(map_layer_, settled, stride);
  fillWithStride(provisional_layer_, changing, stride);
  // One colour scale for both.
  const double low = std::min(map_layer_.low, provisional_layer_.low);
  const double high = std::max(map_layer_.high, provisional_layer_.high);
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
  if (first_points_ && !blocks_.empty()) {
    first_points_ = false;
    fitCamera();
  }
  render();
  emit redrawn(mapPointCount());
}

void MapView::fill(PointLayer& layer, const std::vector<const MapViewBlock*>& blocks,
                   std::size_t max_points) {
  const std::size_t total = countInside(blocks, clipRegion());
  fillWithStride(layer, blocks, total <= max_points ? 1 : (total + max_points - 1) / max_points);
}

void MapView::fillWithStride(PointLayer& layer, const std::vector<const MapViewBlock*>& blocks,
                             std::size_t stride) {
  const std::size_t total = countInside(blocks, clipRegion());
  layer.stride = stride;
  const auto n = static_cast<vtkIdType>((total + layer.stride - 1) / layer.stride);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(n);
  auto* xyz = static_cast<float*>(points->GetVoidPointer(0));
  forEachDrawn(blocks, clipRegion(), layer.stride, [&](const MapViewBlock& b, std::size_t k) {
    const Eigen::Vector3f& p = b.points[k];
    xyz[0] = p.x();
    xyz[1] = p.y();
    xyz[2] = p.z();
    xyz += 3;
  });
  layer.poly->SetPoints(points);
  layer.poly->SetVerts(pointCells(n, false));
  colour(layer, blocks, layer.stride, clipRegion());
}

void MapView::fillMesh() {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh_block_.points.size()));
  for (std::size_t i = 0; i < mesh_block_.points.size(); ++i) {
    const Eigen::Vector3f& v = mesh_block_.points[i];
    points->SetPoint(static_cast<vtkIdType>(i), v.x(), v.y(), v.z());
  }
  // A triangle is drawn when its centre lies in the clip.
  const Eigen::AlignedBox3d* region = clipRegion();
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& t : mesh_triangles_) {
    const Eigen::Vector3f centre =
        (mesh_block_.points[t[0]] + mesh_block_.points[t[1]] + mesh_block_.points[t[2]]) / 3.0f;
    if (region == nullptr || region->contains(centre.cast<double>())) {
      const vtkIdType ids[3] = {t[0], t[1], t[2]};
      triangles->InsertNextCell(3, ids);
    }
  }
  mesh_layer_.poly->Initialize();  // drops the previous mesh's points, cells and values
  mesh_layer_.poly->SetPoints(points);
  mesh_layer_.poly->SetPolys(triangles);
  mesh_layer_.stride = 1;
  if (mesh_normals_.size() == mesh_block_.points.size()) {
    auto normals = vtkSmartPointer<vtkFloatArray>::New();
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(static_cast<vtkIdType>(mesh_normals_.size()));
    for (std::size_t i = 0; i < mesh_normals_.size(); ++i) {
      normals->SetTypedTuple(static_cast<vtkIdType>(i), mesh_normals_[i].data());
    }
    mesh_layer_.poly->GetPointData()->SetNormals(normals);
  }
  colour(mesh_layer_, {&mesh_block_}, 1, nullptr);  // the clip drops triangles, not vertices
}

const Eigen::AlignedBox3d* MapView::clipRegion() const {
  return clip_.active() ? &clip_region_ : nullptr;
}

void MapView::setClip(const ViewClip& clip) {
  clip_ = clip;
  clip_region_ = clip.region();
  fillMap();
  fill(surface_layer_, {&surface_}, std::numeric_limits<std::size_t>::max());
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
  for (const MapViewBlock* b : {&surface_, &mesh_block_}) {
    for (const auto& p : b->points) {
      bounds.extend(p.cast<double>());
    }
  }
  return bounds;
}

void MapView::recolour() {
  fillMap();
  colour(surface_layer_, {&surface_}, surface_layer_.stride, clipRegion());
  colour(mesh_layer_, {&mesh_block_}, 1, nullptr);
}

void MapView::colour(PointLayer& layer, const std::vector<const MapViewBlock*>& blocks,
                     std::size_t stride, const Eigen::AlignedBox3d* region) {
  auto scalars = vtkSmartPointer<vtkFloatArray>::New();
  scalars->SetNumberOfValues(layer.poly->GetNumberOfPoints());
  const ColourBy by =
      colour_by_ == ColourBy::Error && !has_errors_ ? ColourBy::Intensity : colour_by_;
  vtkIdType i = 0;
  std::vector<float> intensities;
  forEachDrawn(blocks, region, stride, [&](const MapViewBlock& b, std::size_t k) {
    float v = k < b.values.size() ? b.values[k] : 0.0f;
    if (by == ColourBy::Depth) {
      v = b.points[k].z();
    } else if (by == ColourBy::Error) {
      v = k < b.errors_m.size() ? b.errors_m[k] : 0.0f;
    } else {
      intensities.push_back(v);
    }
    scalars->SetValue(i++, v);
  });
  double range[2] = {0.0, 1.0};
  if (by == ColourBy::Error) {
    range[1] = 0.10;  // the evaluation's "floating point" distance
  } else if (by == ColourBy::Intensity && !intensities.empty()) {
    const auto hi = intensities.begin() +
                    static_cast<std::ptrdiff_t>(0.98 * static_cast<double>(intensities.size() - 1));
    std::nth_element(intensities.begin(), hi, intensities.end());
    range[1] = std::max(1.0, static_cast<double>(*hi));
  } else if (layer.poly->GetNumberOfPoints() > 0) {
    scalars->GetRange(range);
  }
  layer.poly->GetPointData()->SetScalars(scalars);
  auto* mapper = vtkPolyDataMapper::SafeDownCast(layer.actor->GetMapper());
  const auto& colours = by == ColourBy::Error ? errorColours() : viridisColours();
  mapper->SetLookupTable(lookupTable(colours.data(), static_cast<int>(colours.size())));
  mapper->SetScalarRange(range[0], std::max(range[1], range[0] + 1e-6));
  mapper->ScalarVisibilityOn();
  layer.coloured_by = by;
  layer.low = range[0];
  layer.high = std::max(range[1], range[0] + 1e-6);
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
      legend_->setScale(tr("intensity (counts)"), shown->low, shown->high, viridisColours());
      break;
  }
  legend_->move(8, height() - legend_->height() - 8);
  legend_->show();
  legend_->raise();
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
  triad_->raise();
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
  scale_bar_->raise();
}

QString MapView::pickAt(QPoint position, Eigen::Vector3d* ned) {
  const PointLayer* shown = layer_ == Layer::Map       ? &map_layer_
                            : layer_ == Layer::Surface ? &surface_layer_
                                                       : nullptr;
  if (shown == nullptr || shown->poly->GetNumberOfPoints() == 0) {
    return {};
  }
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
      what = tr("intensity %1 counts").arg(value, 0, 'f', 0);
      break;
  }
  return tr("N %1 E %2 D %3 m, %4")
      .arg(p[0], 0, 'f', 2)
      .arg(p[1], 0, 'f', 2)
      .arg(p[2], 0, 'f', 2)
      .arg(what);
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
  mesh_block_ = MapViewBlock{0, mesh.vertices, mesh.intensity, std::move(vertex_errors_m)};
  mesh_block_.values.resize(mesh.vertices.size(), 0.0f);
  has_errors_ = has_errors_ || !mesh_block_.errors_m.empty();
  mesh_triangles_ = mesh.triangles;
  mesh_normals_ = mesh.normals;
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
