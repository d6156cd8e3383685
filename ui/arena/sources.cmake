# arena: the arena view (walls, map, path, robot, estimate, covariance ellipses, IR rays,
# beacons, laser scans).
list(APPEND LEGOFEUP_UI_SOURCES
    arena/arena_cache.cpp
    arena/arena_colors.cpp
    arena/arena_legend.cpp
    arena/arena_painter.cpp
    arena/arena_painter_lessons.cpp
    arena/arena_view.cpp
    arena/covariance_ellipse.cpp
    arena/history_layer.cpp
    arena/laser_layer.cpp
    arena/map_image.cpp
    arena/thinned_polyline.cpp
    arena/world_camera.cpp
    include/legofeup/ui/arena/arena_view.hpp  # Q_OBJECT: listed for AUTOMOC
)
