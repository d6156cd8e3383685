# The calibration dialogs (Tools menu): the IR sensor's curve and UMBmark, saved to the robot
# profile.
list(APPEND LEGOFEUP_UI_SOURCES
    calibration/ir_calibration_dialog.cpp
    calibration/number_table.cpp
    calibration/profile_file.cpp
    calibration/umbmark_dialog.cpp
    include/legofeup/ui/calibration/ir_calibration_dialog.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/calibration/umbmark_dialog.hpp  # Q_OBJECT: listed for AUTOMOC
)
