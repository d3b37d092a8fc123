"""Throw against cut angle, from Python: the study `termpool experiment throw` prints.

A cue ball arrives at SPEED (stunned: sliding without spin, or rolling) and cuts an object
ball; the throw is how far the object ball leaves off the line of centres. Prints
`cut_deg,throw_deg` for every degree from 0 to 60, as `termpool experiment throw --csv` does
for one cue and speed.

    python3 throw.py [SPEED] [stun|rolling]
"""
import math
import sys

import termpool

APPROACH_GAP = 1e-6  # m: the cue ball starts this close, so it arrives as it was struck


def throw_deg(speed, cut_deg, rolling=False, physics=None):
    physics = physics or termpool.Physics()
    table = termpool.Table("9ft", physics["R"])
    R = physics["R"]
    cut = math.radians(cut_deg)
    cue = termpool.Ball(0, 1.0, table.width / 2)
    target = termpool.Ball(1, 1.0 + APPROACH_GAP + 2 * R * math.cos(cut),
                           table.width / 2 + 2 * R * math.sin(cut))
    # A centre hit leaves the cue ball sliding without spin; 0.4 R of follow is natural roll.
    strike = termpool.Strike(speed, 0, 0, 0.4 if rolling else 0.0)
    shot = termpool.simulate([cue, target], strike, table, physics)
    contact = next(i for i, e in enumerate(shot.events) if e.kind == "ball-ball")
    state = shot.event_state(contact)
    cx = state.other_after.position[0] - state.ball_after.position[0]
    cy = state.other_after.position[1] - state.ball_after.position[1]
    vx, vy = state.other_after.velocity
    return math.degrees(math.atan2(cy, cx) - math.atan2(vy, vx))


def main():
    speed = float(sys.argv[1]) if len(sys.argv) > 1 else 0.3
    rolling = len(sys.argv) > 2 and sys.argv[2] == "rolling"
    print("cut_deg,throw_deg")
    for cut in range(0, 61):
        print(f"{cut},{throw_deg(speed, cut, rolling)!r}")


if __name__ == "__main__":
    main()
