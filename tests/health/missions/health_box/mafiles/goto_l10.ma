behavior_name=goto_list
# A 600 m box from the SIL's launch point (comet 2019's first fix), twice round.
<start:b_arg>
    b_arg: start_when(enum)          0
    b_arg: list_stop_when(enum)      7   # a waypoint is reached within list_when_wpt_dist
    b_arg: list_when_wpt_dist(m)    80
    b_arg: initial_wpt(enum)        -1
    b_arg: num_waypoints(nodim)      4
    b_arg: num_legs_to_run(nodim)    8   # twice round (~3 h)
<end:b_arg>
<start:waypoints>
724.5880 5419.2900
725.1430 5419.2900
725.1430 5418.9660
724.5880 5418.9660
<end:waypoints>
