behavior_name=yo
<start:b_arg>
    b_arg: start_when(enum)              2
    b_arg: num_half_cycles_to_do(nodim) -1   # until the list is done
    b_arg: d_target_depth(m)            40
    b_arg: d_use_pitch(enum)             3   # pitch servo
    b_arg: d_pitch_value(X)        -0.4537   # -26 deg
    b_arg: d_bpump_value(X)          -1000
    b_arg: c_target_depth(m)             5
    b_arg: c_use_pitch(enum)             3
    b_arg: c_pitch_value(X)         0.4537
    b_arg: c_bpump_value(X)           1000
<end:b_arg>
