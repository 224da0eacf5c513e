behavior_name=goto_list
# One waypoint 20 km south of the SIL's launch point (comet 2019's first fix):
# never reached in the ~3 h the mission flies, so a glider launched heading
# 180 deg flies a straight transect with no turn at all.
<start:b_arg>
    b_arg: start_when(enum)          0
    b_arg: list_stop_when(enum)      7   # a waypoint is reached within list_when_wpt_dist
    b_arg: list_when_wpt_dist(m)    80
    b_arg: initial_wpt(enum)        -1
    b_arg: num_waypoints(nodim)      1
    b_arg: num_legs_to_run(nodim)    1
<end:b_arg>
<start:waypoints>
724.5880 5408.1660
<end:waypoints>
