#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""TEST FIXTURE: a glider's shore folder as glider-shore writes it (docs/comms.md,
"Surfacing event", schema glider-shore-surfacing/1), for console tests that
need a given state (an abort, a call in progress) without flying SIL."""
import datetime
import json
import os


def stamp(t):
    return t.strftime("%Y%m%dT%H%M%S")


def iso(t):
    return t.strftime("%Y-%m-%dT%H:%M:%SZ")


def write_call(root, glider, ago_s, n, prompt="GliderDos I -1 >", lat=54.3161, lon=7.4097, aborts=0,
               cause="", event=True):
    """One call that started ago_s seconds ago (with its event unless event=False: a call in progress)."""
    t = datetime.datetime.now(datetime.timezone.utc) - datetime.timedelta(seconds=ago_s)
    call_id = "%s_%04d" % (stamp(t), n)
    logs = os.path.join(root, glider, "logs")
    os.makedirs(logs, exist_ok=True)
    with open(os.path.join(logs, call_id + ".journal"), "w") as f:
        f.write("%s * call from 127.0.0.1:1\n%s < Because:Stack idle [behavior surface start_when = 1.0]\n"
                % (iso(t), iso(t)))
    if not event:
        return call_id
    e = {"schema": "glider-shore-surfacing/1", "glider": glider, "vehicle_name": glider, "peer": "127.0.0.1:1",
         "call_start_utc": iso(t), "call_end_utc": iso(t + datetime.timedelta(seconds=1)), "call_duration_s": 1.0,
         "end_reason": "hangup", "journal": call_id + ".journal",
         "glider_time": {"text": "", "utc": iso(t), "mission_time_s": 100.0 * n},
         "reasons": ["Stack idle [behavior surface start_when = 1.0]"],
         "mission": {"name": "box.mi", "number": glider + "-0"},
         "gps": {"kind": "gps", "lat_deg": lat, "lon_deg": lon, "age_s": 0.0},
         "aborts": {"total_since_reset": aborts, "last_cause": cause, "last_details": "", "last_time": "",
                    "last_segment": "", "last_mission": ""},
         "prompt": prompt, "files_received": [], "files_sent": [], "commands_sent": []}
    tmp = os.path.join(logs, "." + call_id + ".tmp")
    with open(tmp, "w") as f:
        json.dump(e, f)
    os.rename(tmp, os.path.join(logs, call_id + ".surfacing.json"))
    return call_id
