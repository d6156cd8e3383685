# The panels beside the arena: configuration, experiments, the covariance matrix.
list(APPEND LEGOFEUP_UI_SOURCES
    panels/config_panel.cpp
    panels/covariance_view.cpp
    panels/experiment_panel.cpp
    panels/log_slider.cpp
    panels/number_text.cpp
    panels/robot_status.cpp
    panels/setting_editor.cpp
    include/legofeup/ui/panels/config_panel.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/panels/covariance_view.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/panels/experiment_panel.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/panels/log_slider.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/panels/robot_status.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/panels/setting_editor.hpp  # Q_OBJECT: listed for AUTOMOC
)
