behavior_name=goto_list
# SPDX-License-Identifier: Apache-2.0
# One waypoint 150 m east of the launch point, reached within 30 m.
<start:b_arg>
    b_arg: start_when(enum)          0
    b_arg: list_stop_when(enum)      7   # a waypoint is reached within list_when_wpt_dist
    b_arg: list_when_wpt_dist(m)    30
    b_arg: initial_wpt(enum)        -1
    b_arg: num_waypoints(nodim)      1
    b_arg: num_legs_to_run(nodim)    1
<end:b_arg>
<start:waypoints>
724.7266 5418.9660
<end:waypoints>
