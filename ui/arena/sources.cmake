# arena: the arena view (walls, map, path, robot, estimate, covariance ellipses) and its
# parts: camera, legend, kidnap picker, caches, the frame's painting and the lessons' layers
# (IR rays, beacons, laser scans), listed in arena_layers.cpp.
list(APPEND LEGOFEUP_UI_SOURCES
    arena/arena_cache.cpp
    arena/arena_camera.cpp
    arena/arena_colors.cpp
    arena/arena_layers.cpp
    arena/arena_legend.cpp
    arena/arena_painter.cpp
    arena/arena_painter_lessons.cpp
    arena/arena_renderer.cpp
    arena/arena_view.cpp
    arena/beacons_layer.cpp
    arena/covariance_ellipse.cpp
    arena/history_layer.cpp
    arena/ir_rays_layer.cpp
    arena/laser_layer.cpp
    arena/laser_scans_layer.cpp
    arena/legend_placement.cpp
    arena/legend_rows.cpp
    arena/map_image.cpp
    arena/map_pictures.cpp
    arena/particle_cloud_layer.cpp
    arena/pose_picker.cpp
    arena/thinned_polyline.cpp
    arena/world_camera.cpp
    include/legofeup/ui/arena/arena_view.hpp  # Q_OBJECT: listed for AUTOMOC
)
