behavior_name=yo
# RECONSTRUCTED from comet's 2016 logs (README.md).
<start:b_arg>
    b_arg: start_when(enum)                2
    b_arg: num_half_cycles_to_do(nodim)    8   # logged: 8 inflections from each dive to x_surface_active 3
    b_arg: d_target_depth(m)              40   # logged: c_dive_target_depth 40 (turned at 41.4-41.8 m)
    b_arg: d_use_pitch(enum)               3   # pitch servo: logged c_climb_battpos changing (servo memory,
    b_arg: d_pitch_value(X)          -0.4363   # u_use_pitch_servo_memory 1); f_nominal_pitch 0.4363; median
    b_arg: d_bpump_value(X)            -1000   # glide pitch -25.2 / +26.0 deg; c_ballast_pumped -233 / +233
    b_arg: c_target_depth(m)             1.5   # logged: c_climb_target_depth 1; this firmware refuses a climb
                                               # target at or above its surfaced depth (1 m): the nearest it flies
    b_arg: c_use_pitch(enum)               3
    b_arg: c_pitch_value(X)           0.4363
    b_arg: c_bpump_value(X)             1000
<end:b_arg>
