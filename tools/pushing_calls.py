#!/usr/bin/env python3
"""Where the referee's pushing calls come from: for each pushing penalty in a match's LCM
event log (TL_EVENT), the pair's motion before the call, from TL_TRUTH. Reads logs; writes
one JSON line per call (--calls) and a summary of the distribution to stdout.

For each call, judged on the truth frame before it (the call's own frame already shows the
pusher on its bench): the victim is the pusher's nearest opponent (as the match picks the
robot that may fall); over each of WINDOWS_S before the call, each robot's speed
towards the other (its body's displacement along the line from it to the other, divided
by the window: + walking into the other, - backing away), both robots' distances to the
ball, how long the pair had been in contact (body centres closer than CONTACT_MM) when
the call came, each robot's role (its last team message before the call: team_comm.py's
byte 2, as match_stats.py reads it) and where the victim was as the pusher faced
(victim_bearing_deg, 0 straight ahead: within SENSED_BEARING_DEG the sonars and the middle
of the camera's view can see it, so avoidance can act); how long before the call the victim
was last inside the pusher's camera view (victim_in_view_s_ago: the cone of the log's
TL_MATCH camera field of view about the heading plus the head yaw the pusher's TL_ACT
reported, out to the camera's farthest reach; misses and occlusion not counted; None: not
within HISTORY_S); and which way the pusher's body moved over the last 0.5 s, from its
heading (pusher_moving_deg, 0 forward, 90 to its left, 180 backwards; None if it stood).

  tools/pushing_calls.py LOG... [--calls calls.jsonl]
"""
from __future__ import annotations

import argparse
import json
import math
import statistics
import sys
from pathlib import Path

import touchline_paths
from match_stats import message_role
from touchline_version import add_version_option

CONTACT_MM = 300.0        # rules.contact_distance_mm's default
WINDOWS_S = (0.25, 0.5, 1.0)
HISTORY_S = 10.0          # truth kept per robot: enough to time a long contact
SENSED_BEARING_DEG = 30.0  # deg: a victim this far off the pusher's heading is in its sonars' and camera's middle
CAMERA_FOV_RAD = math.radians(60)   # the camera's cone and ...
CAMERA_REACH_MM = 4000.0            # ... farthest reach when the log has no TL_MATCH (the defaults)
SIDEWAYS_DEG = 45.0                 # deg: a pusher moving more than this off its heading walked sideways or backwards


def towards(h: list, other: tuple, window_s: float) -> float | None:
    """Speed of the robot whose (utime, x, y) samples end `h` towards the point `other`
    (x, y), mm/s, over the last window_s; None if the history is shorter or the robot was
    placed (a jump of over 200 mm in a frame) within the window."""
    t1, x1, y1 = h[-1]
    older = [i for i, s in enumerate(h) if s[0] <= t1 - window_s * 1e6]
    if not older:
        return None
    t0, x0, y0 = h[older[-1]]
    window = h[older[-1]:]
    if any(math.hypot(b[1] - a[1], b[2] - a[2]) > 200 for a, b in zip(window, window[1:])):
        return None
    dx, dy = other[0] - x1, other[1] - y1
    n = math.hypot(dx, dy) or 1.0
    return ((x1 - x0) * dx + (y1 - y0) * dy) / n / ((t1 - t0) * 1e-6)


def moving_deg(h: list, theta: float, window_s: float = 0.5) -> float | None:
    """Which way the robot whose (utime, x, y) samples end `h`, now heading `theta`, moved over
    the last window_s, deg from its heading (+ left), or None if it moved under 10 mm."""
    t1, x1, y1 = h[-1]
    older = [s for s in h if s[0] <= t1 - window_s * 1e6]
    if not older:
        return None
    _, x0, y0 = older[-1]
    if math.hypot(x1 - x0, y1 - y0) < 10:
        return None
    return math.degrees(math.remainder(math.atan2(y1 - y0, x1 - x0) - theta, 2 * math.pi))


def in_view(viewer, other, head_yaw: float, fov_rad: float, reach_mm: float) -> bool:
    """Whether robot truth `other` stands in the camera cone of robot truth `viewer`."""
    dx, dy = other.body.x_mm - viewer.body.x_mm, other.body.y_mm - viewer.body.y_mm
    bearing = math.remainder(math.atan2(dy, dx) - viewer.body.theta_rad - head_yaw, 2 * math.pi)
    return abs(bearing) <= fov_rad / 2 and math.hypot(dx, dy) <= reach_mm


def analyse(log: Path) -> list[dict]:
    import lcm
    from touchline import act_t, match_config_t, match_event_t, world_truth_t

    history: dict[tuple, list] = {}   # (team, player) -> [(utime, x, y)] while on the field
    contact_since: dict[tuple, int] = {}  # (id, id) sorted -> utime contact began
    # The penalty's event follows the truth of the frame it was judged on, which already shows
    # the pusher on its bench: calls are judged on the frame before (`last`), with the history
    # and contacts as they were then.
    last = current = None
    contact_before: dict[tuple, int] = {}
    calls = []
    roles: dict[tuple, str] = {}  # (team, player) -> the role of its last team message
    head_yaw: dict[tuple, float] = {}  # (team, player) -> its last reported head yaw, rad
    fov_rad, reach_mm = CAMERA_FOV_RAD, CAMERA_REACH_MM
    seen_at: dict[tuple, int] = {}  # (viewer id, other id) -> utime the other was last in the viewer's view
    for event in lcm.EventLog(str(log), "r"):
        if event.channel == "TL_MATCH":
            config = match_config_t.decode(event.data)
            fov_rad, reach_mm = config.camera_field_of_view_rad, config.camera_near_range_mm + config.camera_range_span_mm
        elif event.channel.startswith("TL_ACT_"):
            act = act_t.decode(event.data)
            head_yaw[(act.team, act.player)] = act.head_yaw_rad
            if role := message_role(act):
                roles[(act.team, act.player)] = role
        elif event.channel == "TL_TRUTH":
            truth = world_truth_t.decode(event.data)
            last, current = current, truth
            contact_before = dict(contact_since)
            on = [r for r in truth.robots if not r.penalised]
            for r in truth.robots:
                key = (r.team, r.player)
                if not r.penalised:
                    history.setdefault(key, []).append((truth.utime, r.body.x_mm, r.body.y_mm))
                h = history.get(key, [])
                while h and h[0][0] < truth.utime - HISTORY_S * 1e6:
                    del h[0]
            for a in on:
                for b in on:
                    if a is not b and in_view(a, b, head_yaw.get((a.team, a.player), 0.0), fov_rad, reach_mm):
                        seen_at[((a.team, a.player), (b.team, b.player))] = truth.utime
            for i, a in enumerate(on):
                for b in on[i + 1:]:
                    key = ((a.team, a.player), (b.team, b.player))
                    if math.hypot(a.body.x_mm - b.body.x_mm, a.body.y_mm - b.body.y_mm) < CONTACT_MM:
                        contact_since.setdefault(key, truth.utime)
                    else:
                        contact_since.pop(key, None)
        elif event.channel == "TL_EVENT" and last is not None:
            e = match_event_t.decode(event.data)
            if e.kind != match_event_t.PENALTY or e.text != "pushing":
                continue
            robots = {(r.team, r.player): r for r in last.robots}
            p = robots.get((e.team, e.player))
            if p is None:
                continue
            victims = [r for r in last.robots if r.team != e.team and not r.penalised]
            dist = {(v.team, v.player): math.hypot(v.body.x_mm - p.body.x_mm, v.body.y_mm - p.body.y_mm)
                    for v in victims}
            if not dist:
                continue
            vkey = min(dist, key=dist.get)
            v = robots[vkey]
            pkey = (e.team, e.player)
            call = {"log": log.name, "utime": e.utime, "pusher": list(pkey), "victim": list(vkey),
                    "distance_mm": dist[vkey],
                    "pusher_ball_mm": math.hypot(p.body.x_mm - last.ball_x_mm, p.body.y_mm - last.ball_y_mm),
                    "victim_ball_mm": math.hypot(v.body.x_mm - last.ball_x_mm, v.body.y_mm - last.ball_y_mm)}
            call["pusher_role"] = roles.get(pkey, "")
            call["victim_role"] = roles.get(vkey, "")
            bearing = math.atan2(v.body.y_mm - p.body.y_mm, v.body.x_mm - p.body.x_mm) - p.body.theta_rad
            call["victim_bearing_deg"] = math.degrees(math.remainder(bearing, 2 * math.pi))
            pair = tuple(sorted([pkey, vkey]))
            since = contact_before.get(pair)
            # 0: not in contact a frame before the call (the contact began in the judged frame).
            call["contact_s"] = (last.utime - since) * 1e-6 if since is not None else 0.0
            hp = [s for s in history.get(pkey, []) if s[0] <= last.utime]
            hv = [s for s in history.get(vkey, []) if s[0] <= last.utime]
            for w in WINDOWS_S:
                call[f"pusher_towards_{w}"] = towards(hp, (v.body.x_mm, v.body.y_mm), w) if hp else None
                call[f"victim_towards_{w}"] = towards(hv, (p.body.x_mm, p.body.y_mm), w) if hv else None
            seen = seen_at.get((pkey, vkey))
            call["victim_in_view_s_ago"] = (
                (last.utime - seen) * 1e-6 if seen is not None and last.utime - seen <= HISTORY_S * 1e6 else None)
            call["pusher_moving_deg"] = moving_deg(hp, p.body.theta_rad) if hp else None
            calls.append(call)
    if current is None:
        raise ValueError("holds no TL_TRUTH: not a match log")
    return calls


def quantiles(values: list) -> str:
    values = sorted(x for x in values if x is not None)
    if not values:
        return "none"
    q = [values[min(len(values) - 1, int(f * len(values)))] for f in (0.1, 0.25, 0.5, 0.75, 0.9)]
    return (f"n={len(values)} p10 {q[0]:.0f} p25 {q[1]:.0f} median {q[2]:.0f} p75 {q[3]:.0f} p90 {q[4]:.0f}"
            f" mean {statistics.fmean(values):.0f}")


def share(calls: list, test) -> str:
    n = sum(1 for c in calls if test(c))
    return f"{n}/{len(calls)} ({100 * n / max(1, len(calls)):.0f} %)"


def summarise(calls: list) -> None:
    print(f"pushing calls: {len(calls)}")
    print("distance between bodies, mm:", quantiles([c["distance_mm"] for c in calls]))
    print("pusher to ball, mm:", quantiles([c["pusher_ball_mm"] for c in calls]))
    print("victim to ball, mm:", quantiles([c["victim_ball_mm"] for c in calls]))
    print("contact before the call, ms:", quantiles([c["contact_s"] * 1e3 for c in calls]))
    for w in WINDOWS_S:
        print(f"pusher towards victim over {w} s, mm/s:", quantiles([c[f"pusher_towards_{w}"] for c in calls]))
        print(f"victim towards pusher over {w} s, mm/s:", quantiles([c[f"victim_towards_{w}"] for c in calls]))
    for threshold in (25, 50, 75, 100):
        key = "pusher_towards_0.5"
        print(f"pusher walking into the victim > {threshold} mm/s over 0.5 s:",
              share(calls, lambda c, t=threshold: c[key] is not None and c[key] > t))
        print(f"  ... or victim walking into the pusher > {threshold} mm/s:",
              share(calls, lambda c, t=threshold: (c[key] or 0) > t or (c["victim_towards_0.5"] or 0) > t))
    print("neither moving towards the other (both <= 25 mm/s over 0.5 s):",
          share(calls, lambda c: (c["pusher_towards_0.5"] or 0) <= 25 and (c["victim_towards_0.5"] or 0) <= 25))
    print("both within 700 mm of the ball:",
          share(calls, lambda c: c["pusher_ball_mm"] < 700 and c["victim_ball_mm"] < 700))
    print(f"victim within {SENSED_BEARING_DEG:.0f} deg of the pusher's heading:",
          share(calls, lambda c: abs(c["victim_bearing_deg"]) <= SENSED_BEARING_DEG))
    print("victim in the pusher's camera view within 1.5 s before the call:",
          share(calls, lambda c: c["victim_in_view_s_ago"] is not None and c["victim_in_view_s_ago"] <= 1.5))
    print("... within 3 s:",
          share(calls, lambda c: c["victim_in_view_s_ago"] is not None and c["victim_in_view_s_ago"] <= 3.0))
    print(f"pusher moving sideways or backwards (over {SIDEWAYS_DEG:.0f} deg off its heading, last 0.5 s):",
          share(calls, lambda c: c["pusher_moving_deg"] is not None and abs(c["pusher_moving_deg"]) > SIDEWAYS_DEG))
    for role in sorted({c["pusher_role"] for c in calls}):
        print(f"pusher's role {role or '(none)'}:", share(calls, lambda c, r=role: c["pusher_role"] == r))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    add_version_option(parser, "tools/pushing_calls.py")
    parser.add_argument("logs", nargs="+", type=Path)
    parser.add_argument("--calls", type=Path, help="write every call as a JSON line here")
    parser.add_argument("--build-dir", type=Path, default=touchline_paths.build_dir())
    args = parser.parse_args()
    for types in touchline_paths.lcm_python_dirs(args.build_dir):
        if types not in sys.path:
            sys.path.insert(0, types)
    calls = []
    for log in args.logs:
        try:
            calls += analyse(log)
        except (OSError, ValueError) as e:  # no such file, not an LCM log, no TL_MATCH
            print(f"pushing_calls: {log}: {getattr(e, 'strerror', None) or e}", file=sys.stderr)
            return 1
    if args.calls:
        args.calls.write_text("".join(json.dumps(c) + "\n" for c in calls))
    summarise(calls)
    return 0


if __name__ == "__main__":
    sys.exit(main())
