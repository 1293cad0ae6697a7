# What lesson steps show when they open, from --log-frames of the real editor under Xvfb (no clicks).
# See ui_lesson_views.sh.
gbl_xdotool_test(ui_lesson_views TIMEOUT 300)
