#pragma once
// The arena's cache of map pictures (map_image.hpp): the world's occupancy-grid map and the
// laser filter's own map when it differs (an outdated one, tinted, over the world's). A map
// never changes during a run, so each picture is made once per map and per palette.

#include <QImage>
#include <QRgb>

#include "legofeup/ui/arena/arena_colors.hpp"
#include "legofeup/ui/run_history.hpp"

namespace legofeup::ui {

class MapPictures {
  public:
    /// Remakes a picture when the scene's map or the occupied colour changed.
    void update(const ArenaScene& scene, const ArenaColors& colors);
    /// The world's map, one pixel per cell; null without one.
    const QImage& world_map() const { return world_map_; }
    /// The filter's map when it is not the world's; null otherwise.
    const QImage& filter_map() const { return filter_map_; }

  private:
    QImage world_map_;
    QImage filter_map_;
    const OccupancyGrid* world_source_ = nullptr;
    const OccupancyGrid* filter_source_ = nullptr;
    QRgb colour_ = 0;  ///< the occupied colour the pictures were made with
};

}  // namespace legofeup::ui
