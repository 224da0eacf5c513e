behavior_name=surface
<start:b_arg>
    b_arg: when_secs(sec)         1800   # a fix every 30 min
    b_arg: end_action(enum)          2   # resume
    b_arg: gps_wait_time(s)        300
<end:b_arg>
