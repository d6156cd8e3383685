# The panels beside the arena: configuration, the covariance matrix, the Robot dock.
list(APPEND LEGOFEUP_UI_SOURCES
    panels/config_panel.cpp
    panels/covariance_view.cpp
    panels/log_slider.cpp
    panels/message_line.cpp
    panels/number_text.cpp
    panels/robot_status.cpp
    panels/setting_editor.cpp
    include/legofeup/ui/panels/config_panel.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/panels/covariance_view.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/panels/log_slider.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/panels/robot_status.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/panels/setting_editor.hpp  # Q_OBJECT: listed for AUTOMOC
)
