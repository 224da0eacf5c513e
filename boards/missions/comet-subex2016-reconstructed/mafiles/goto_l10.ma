behavior_name=goto_list
# RECONSTRUCTED from comet's 2016 logs (README.md). The waypoints are the glider's own c_wpt_lat/lon:
# 5443.000 N 1506.500 E from the mission's start (segment 000, 26 s) until the pilot's change at
# 7056 s (segment 002, at the surface: x_hit_a_waypoint stayed 0, no waypoint was reached), then
# 5444.090 N 1506.400 E. The real list held at least these two; its other arguments are assumed.
<start:b_arg>
    b_arg: start_when(enum)          0
    b_arg: list_stop_when(enum)      7
    b_arg: list_when_wpt_dist(m)   500   # assumed (nsb3's goto_l10.ma)
    b_arg: initial_wpt(enum)        -1
    b_arg: num_waypoints(nodim)      2
    b_arg: num_legs_to_run(nodim)   -1
<end:b_arg>
<start:waypoints>
1506.500 5443.000
1506.400 5444.090
<end:waypoints>
