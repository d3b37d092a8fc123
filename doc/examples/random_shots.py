"""Simulates N random shots at the 8-ball rack from Python, the loop of random_shots.cpp, and
prints the same sum over the final positions (the same simulator, to the last digit) and how
long the loop took; then the same shots in one simulate_many call across threads.

    python3 random_shots.py 10000
"""
import sys
import time

import termpool

MASK = (1 << 64) - 1


class Stream:
    """splitmix64, as random_shots.cpp draws it."""

    def __init__(self, seed):
        self.state = seed

    def next(self):
        self.state = (self.state + 0x9E3779B97F4A7C15) & MASK
        z = self.state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
        return ((z ^ (z >> 31)) >> 11) * 2.0**-53


def strikes(count):
    stream = Stream(2026)
    out = []
    for _ in range(count):
        speed = 0.5 + 7.5 * stream.next()
        angle = 360 * stream.next()
        side = 0.6 * (stream.next() - 0.5)
        follow = 0.6 * (stream.next() - 0.5)
        out.append(termpool.Strike(speed, angle, side, follow))
    return out


def main():
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 10000
    physics = termpool.Physics()
    table = termpool.Table("9ft")
    balls = termpool.rack("8ball", table, physics)
    batch = strikes(count)  # drawn before the clock starts; the C++ loop draws as it goes
    total = 0.0
    events = 0
    wall, cpu = time.perf_counter(), time.process_time()
    for strike in batch:
        shot = termpool.simulate(balls, strike, table, physics, trajectory=False)
        events += shot.event_count
        x, y = shot.ball(0).position
        total += x + y
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    print(f"termpool {termpool.__version__}: {count} shots, {events} events, "
          f"cue ball sum {total!r}")
    print(f"{wall:.3f} s wall, {cpu:.3f} s CPU, {1e6 * cpu / count:.1f} us a shot")

    wall, cpu = time.perf_counter(), time.process_time()
    shots = termpool.simulate_many(balls, batch, table, physics)
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    same = sum(s.ball(0).position[0] + s.ball(0).position[1] for s in shots)
    print(f"simulate_many: {wall:.3f} s wall, {cpu:.3f} s CPU on every thread, "
          f"cue ball sum {same!r}")


if __name__ == "__main__":
    main()
