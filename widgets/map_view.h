// MapView: the 3D map as it grows, in world NED coordinates (metres), drawn with VTK inside a
// VtkGlWidget. Three layers, one shown at a time: the carved map (occupied voxels, live), the
// surface points that occlusion resolution keeps, and the surface mesh; points are coloured by
// intensity, depth or error against the ground truth. Also the sonar's track, the current
// frame's frustum and its fan in 3D. Updates carry only the blocks that changed; the view keeps its
// own copy of the blocks within a budget of points (MapLod: every voxel while it fits, coarser
// levels for the blocks the survey has left when it does not) and redraws at most every
// `kRedrawInterval_ms`. GUI thread only.
#pragma once

#include <vtkSmartPointer.h>
#include <Eigen/Geometry>
#include <QPointF>
#include <QTimer>
#include <QVector3D>
#include <QWidget>
#include <array>
#include <map>
#include <opencv2/core.hpp>
#include <optional>
#include <string_view>
#include <vector>

#include "map_layers.h"
#include "map_lod.h"
#include "mesh/surface_mesher.h"
#include "session/camera_state.h"
#include "sonar/sonar_model.h"
#include "view_clip.h"

class vtkActor;
class vtkPolyData;
class QLabel;

namespace sonarcarve::widgets {

class AxesTriad;
class ColourLegend;
class ScaleBar;
class VtkGlWidget;

/// Where the camera is, to save and restore a view (session/camera_state.h).
using CameraState = sonarcarve::CameraState;

class MapView : public QWidget {
  Q_OBJECT
 public:
  using ColourBy = widgets::ColourBy;
  enum class Layer { Map, Surface, Mesh };
  /// "intensity", "depth", "error": the names sessions and the command line use.
  static const char* nameOf(ColourBy by);
  /// The colouring of a name; Intensity for an unknown one.
  static ColourBy colourByNamed(std::string_view name);
  static constexpr int kRedrawInterval_ms = 200;
  /// The carved map is drawn with at most this many points (every n-th voxel): software
  /// OpenGL on 2 cores took 30 to 90 ms for 90,000 points while carving, and the GUI thread
  /// must not block for more than 50 ms. A point held at a coarser level of detail counts the
  /// voxels it stands for (map_layers.h, preparePoints). The run's own map is what is exported.
  static constexpr std::size_t kMaxDrawnMapPoints = 40000;
  /// While carving, a block of the map changed within this many frames is provisional (the
  /// frames still see it and may carve its voxels away): drawn translucent and smaller.
  static constexpr std::size_t kSettleFrames = 8;

  explicit MapView(QWidget* parent = nullptr);
  ~MapView() override;

  void clearMap();
  /// The view's copy of the carved map's blocks, by block number.
  using MapBlocks = MapLod::Blocks;
  /// As clearMap(), giving the blocks it held to the caller, who can have a worker free them
  /// (a riser's took the GUI thread 130 ms and more).
  [[nodiscard]] MapBlocks takeMap();
  /// Whether a run is carving the map: only then are its recently changed blocks provisional.
  void setLive(bool live);
  /// Points of the carved map drawn as provisional (translucent), as settled (opaque).
  std::size_t provisionalPointCount() const;
  std::size_t settledPointCount() const;
  void applyBlocks(std::vector<MapViewBlock> blocks);
  /// Redraws now instead of at the next redraw tick (for tests and screenshots).
  void flush();
  /// Occupied voxels of the carved map as received so far.
  std::size_t mapPointCount() const { return map_.voxelCount(); }
  /// The points the view holds of the carved map: every occupied voxel while they fit in the
  /// budget, else coarser points for the blocks changed longest ago (MapLod).
  std::vector<Eigen::Vector3f> mapPoints() const;
  std::size_t heldMapPointCount() const { return map_.pointCount(); }
  /// The most points of the carved map the view holds (MapLod::kDefaultMaxPoints unless set).
  void setMapPointBudget(std::size_t max_points);
  std::size_t mapPointBudget() const { return map_.maxPoints(); }
  /// The carved map's voxel size, whose grid the coarser levels follow.
  void setVoxelSize(double voxel_size_m) { map_.setVoxelSize(voxel_size_m); }
  /// The run's surface points (and their errors against the truth, if known).
  void setSurface(MapViewBlock surface);

  /// A run's surface and mesh with their layers built for a colouring and a clip region, on
  /// any thread (prepareResult touches no widget); setResult() then only hands them to VTK.
  struct PreparedResult {
    MapViewBlock surface;
    MeshData mesh;
    ColourBy colour_by = ColourBy::Intensity;   ///< as asked (before falling back)
    std::optional<Eigen::AlignedBox3d> region;  ///< the clip region built for
    PreparedLayer surface_layer;
    PreparedLayer mesh_layer;
  };
  static PreparedResult prepareResult(MapViewBlock surface, MeshData mesh, ColourBy by,
                                      const ViewClip& clip);
  /// Shows a prepared result as setSurface() and setMesh() would; its layers are rebuilt here
  /// only if the colouring or the clip has changed since it was prepared.
  void setResult(PreparedResult result);
  /// How many times the surface's or the mesh's layer (not empty) was built by the view, on
  /// the GUI thread, for tests: setResult() of a result prepared for the view's colouring and
  /// clip builds none.
  std::size_t resultLayersBuiltHere() const { return result_layers_built_here_; }
  void setLayer(Layer layer);
  Layer layer() const { return layer_; }
  /// A line over the view's top-left corner saying what the map is (provisional while carving,
  /// cancelled, failed); empty hides it.
  void setCaption(const QString& text);
  QString caption() const;
  /// The colour key of the layer shown ("depth (m): 9.65 to 11.29"); empty when it is hidden
  /// (the mesh, or nothing drawn yet).
  QString legendText() const;
  /// The point of the layer shown (carved map or surface) under `position` in the widget:
  /// "N 4.31 E -0.05 D 10.12 m, intensity 2345 counts", its world position in `ned`. Empty if
  /// there is none (or the mesh is shown).
  QString pickAt(QPoint position, Eigen::Vector3d* ned = nullptr);
  /// The picks marked in the view, oldest first: at most the last two (those of a distance).
  /// A click that picks a point marks it; the last has a marker, a line joins the two.
  void markPick(const Eigen::Vector3d& ned);
  void clearPicks();
  const std::vector<Eigen::Vector3d>& picks() const { return picks_; }
  /// What the pick marks draw (for tests): the marker's points and the distance line's points,
  /// 0 for one that is hidden.
  std::vector<Eigen::Vector3d> pickMarkerPoints() const;
  std::vector<Eigen::Vector3d> pickLinePoints() const;
  /// Where a world point appears in the widget.
  QPoint screenPositionOf(const Eigen::Vector3d& ned) const;
  /// The north, east and down axes on the screen as the triad in the corner draws them.
  std::array<QPointF, 3> axesOnScreen() const;
  /// The scale bar over the triad (metres at the camera's focal point).
  const ScaleBar& scaleBar() const { return *scale_bar_; }
  bool hasErrors() const { return has_errors_; }

  void setColourBy(ColourBy by);
  ColourBy colourBy() const { return colour_by_; }
  /// What the map's intensities are in, for the legend: "counts" (the default), or the echo's
  /// power for a sonar whose counts are not (decibels, a gamma: sonar/intensity_scale.h).
  void setIntensityUnit(const QString& unit);
  void setTrack(const std::vector<Eigen::Vector3d>& positions_m);
  /// The current frame: its frustum and its polar image drawn as a fan at elevation 0.
  void setCurrentFrame(const Eigen::Isometry3d& T_world_sonar, const SonarModel& sonar,
                       const cv::Mat& image);
  /// The run's mesh, coloured like the points: intensity (each vertex's nearest surface
  /// point), depth, or error against the ground truth (`vertex_errors_m`, empty without one).
  void setMesh(const Mesh& mesh, std::vector<float> vertex_errors_m = {});
  /// Draws only what lies in the clip's box and cross-section (all layers); an inactive clip
  /// draws everything.
  void setClip(const ViewClip& clip);
  const ViewClip& clip() const { return clip_; }
  /// What the layer shown draws: its points (every n-th of the carved map, inside the clip),
  /// and for the mesh its triangles inside the clip.
  std::size_t drawnPointCount() const;
  std::vector<Eigen::Vector3f> drawnPoints() const;
  std::size_t drawnTriangleCount() const;
  /// The bounds of everything received (map, surface and mesh), for the clip's dialog.
  Eigen::AlignedBox3d dataBounds() const;

  void fitCamera();
  void viewFromTop();
  void viewFromSide();
  void setOrthographic(bool on);
  bool orthographic() const;
  CameraState cameraState() const;
  void setCameraState(const CameraState& state);
  /// The 3D view as an image (renders it first).
  QImage grabImage();

 signals:
  /// The carved map was redrawn; `points`: the points the view holds of it.
  void redrawn(std::size_t points);
  /// A click picked a point: pickAt's text and the point's world position (north, east, down).
  void pointPicked(const QString& text, const QVector3D& ned);

 private:
  struct PointLayer {
    vtkSmartPointer<vtkPolyData> poly;
    vtkSmartPointer<vtkActor> actor;
    std::size_t stride = 1;  ///< every stride-th point is drawn
    // The colour scale as last drawn: what the values are and the table's ends.
    ColourBy coloured_by = ColourBy::Intensity;
    double low = 0.0;
    double high = 1.0;
  };
  void updateLegend();
  void updateTriad();
  void updateScaleBar();
  void resizeEvent(QResizeEvent* event) override;
  void redraw();
  void recolour();
  void fillWithStride(PointLayer& layer, const std::vector<const MapViewBlock*>& blocks,
                      std::size_t stride);
  void fillMap();
  void fillSurface();
  void fillMesh();
  /// The colouring drawn for `colour_by_` (error only when errors are known).
  ColourBy shownColouring() const;
  void adopt(PointLayer& layer, PreparedLayer prepared);
  void applyColours(PointLayer& layer, LayerColours colours);
  const PointLayer* shownLayer() const;
  const Eigen::AlignedBox3d* clipRegion() const;
  std::vector<const MapViewBlock*> mapBlocks() const;
  bool provisional(const MapViewBlock& block) const;
  void scheduleRedraw();
  void render();
  void updatePickMarks();

  VtkGlWidget* gl_ = nullptr;
  QLabel* caption_ = nullptr;
  ColourLegend* legend_ = nullptr;
  AxesTriad* triad_ = nullptr;
  ScaleBar* scale_bar_ = nullptr;
  MapLod map_;
  MapViewBlock surface_;
  Layer layer_ = Layer::Map;
  ColourBy colour_by_ = ColourBy::Intensity;
  QString intensity_unit_ = QStringLiteral("counts");
  bool has_errors_ = false;
  bool first_points_ = true;
  QTimer redraw_timer_;
  PointLayer map_layer_;
  PointLayer provisional_layer_;
  bool live_ = false;
  std::size_t latest_frames_done_ = 0;
  PointLayer surface_layer_;
  PointLayer mesh_layer_;
  MeshData mesh_;  // its vertices with their values, to colour it
  std::size_t result_layers_built_here_ = 0;
  ViewClip clip_;
  Eigen::AlignedBox3d clip_region_;
  vtkSmartPointer<vtkActor> track_actor_;
  vtkSmartPointer<vtkActor> frustum_actor_;
  vtkSmartPointer<vtkActor> fan_actor_;
  std::vector<Eigen::Vector3d> picks_;
  vtkSmartPointer<vtkActor> pick_marker_actor_;
  vtkSmartPointer<vtkActor> pick_line_actor_;
};

}  // namespace sonarcarve::widgets
