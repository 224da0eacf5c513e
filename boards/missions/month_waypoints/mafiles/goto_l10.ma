behavior_name=goto_list
# A 40 km square from the launch point, looped.
<start:b_arg>
    b_arg: list_stop_when(enum)      7
    b_arg: list_when_wpt_dist(m)   500
    b_arg: num_waypoints(nodim)      4
    b_arg: num_legs_to_run(nodim)   -1   # loop
<end:b_arg>
<start:waypoints>
724.5880 5440.5497
801.5900 5440.5497
801.5900 5418.9660
724.5880 5418.9660
<end:waypoints>
