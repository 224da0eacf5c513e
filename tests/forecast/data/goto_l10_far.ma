behavior_name=goto_list
# 2 km box, counter-clockwise from the launch point: north, east, south, home.
<start:b_arg>
    b_arg: start_when(enum)          0
    b_arg: list_stop_when(enum)      7   # a waypoint is reached within list_when_wpt_dist
    b_arg: list_when_wpt_dist(m)   150
    b_arg: initial_wpt(enum)        -1
    b_arg: num_waypoints(nodim)      4
    b_arg: num_legs_to_run(nodim)   -2   # once through the list
<end:b_arg>
<start:waypoints>
724.5880 5440.0452
726.4381 5420.0452
726.4381 5418.9660
724.5880 5418.9660
<end:waypoints>
