"""The Python module against the simulator it wraps: the same results as `termpool simulate`,
the same error messages, sampled motion that agrees with the events, and rules that play whole
games. Run by `make test` (tests/test_python.cpp) with PYTHONPATH set to the module built."""
import os
import re
import subprocess
import sys

import pytest

import termpool as tp

BIN = os.environ.get("TERMPOOL_BIN", "build/termpool")


def simulate_cli(scenario, tmp_path):
    path = tmp_path / "shot.txt"
    path.write_text(scenario)
    return subprocess.run([BIN, "simulate", str(path)], capture_output=True, text=True)


def test_version_is_the_programs():
    out = subprocess.run([BIN, "--version"], capture_output=True, text=True).stdout
    assert out.split()[1] == tp.__version__
    assert tp.physics_version >= 2


def test_break_matches_simulate_to_the_bit(tmp_path):
    run = simulate_cli("rack 8ball\nstrike 8 0 0.1 -0.2\n", tmp_path)
    assert run.returncode == 0, run.stderr
    shot = tp.simulate(tp.rack("8ball"), tp.Strike(8, 0, 0.1, -0.2))
    lines = [l.split() for l in run.stdout.splitlines()]
    events = [w for w in lines if w[0] == "event"]
    assert len(events) == shot.event_count
    for words, event in zip(events, shot.events):
        assert float(words[1]) == event.time
        assert words[2] == event.kind
        assert int(words[3]) == event.ball
    finals = {int(w[1]): w for w in lines if w[0] == "ball"}
    assert len(finals) == len(shot.balls)
    for ball in shot.balls:
        words = finals[ball.id]
        assert (float(words[2]), float(words[3])) == ball.position
    assert [float(w[1]) for w in lines if w[0] == "rest"] == [shot.rest_time]


@pytest.mark.parametrize("scenario, call", [
    ("ball 0 0.01 0.5\nstrike 1 0\n", lambda: tp.simulate([tp.Ball(0, 0.01, 0.5)], tp.Strike(1))),
    ("ball 0 1 0.5\nstrike 30 0\n", lambda: tp.simulate([tp.Ball(0, 1, 0.5)], tp.Strike(30))),
    ("ball 0 1 0.5\nstrike 2 0 0.7 0\n",
     lambda: tp.simulate([tp.Ball(0, 1, 0.5)], tp.Strike(2, 0, 0.7))),
    ("ball 0 1 0.5\nball 1 1.03 0.5\nstrike 2 0\n",
     lambda: tp.simulate([tp.Ball(0, 1, 0.5), tp.Ball(1, 1.03, 0.5)], tp.Strike(2))),
])
def test_errors_have_the_words_of_simulate(scenario, call, tmp_path):
    run = simulate_cli(scenario, tmp_path)
    assert run.returncode == 2
    with pytest.raises(ValueError) as error:
        call()
    # simulate says FILE:LINE: MESSAGE and may name another line; the module has no lines.
    said = re.sub(r" \(line [0-9]+\)$", "", run.stderr.strip())
    assert said.endswith(": " + str(error.value)), (run.stderr, str(error.value))


def test_parameters_refused_as_a_scenario_refuses_them(tmp_path):
    physics = tp.Physics()
    for name, value in [("e_b", 1.5), ("u_s", -1), ("mu", 0.2), ("g", 0), ("w_c", 2)]:
        run = simulate_cli(f"param {name} {value}\nball 0 1 0.5\nstrike 1 0\n", tmp_path)
        with pytest.raises(ValueError) as error:
            physics[name] = value
        assert run.stderr.strip().endswith(str(error.value))
    physics["u_s"] = 0.25
    assert physics["u_s"] == 0.25
    with pytest.raises(ValueError, match="unknown cushion model"):
        physics.cushion = "rubber"
    for cushion in ["physical", "ideal", "mirror", "stronge"]:
        physics.cushion = cushion
        assert physics.cushion == cushion
    physics["w_c"] = 1.53
    assert physics["w_c"] == 1.53
    physics.friction = "decay 0.5"
    assert physics.friction == "decay 0.5"
    with pytest.raises(ValueError):
        physics.friction = "decay -1"


def test_models_change_the_outcome():
    balls = [tp.Ball(0, 0.5, 0.4)]
    strike = tp.Strike(2, 30)
    seen = set()
    for cushion in ["physical", "ideal"]:
        for friction in ["physical", "decay 0.5", "constant 0.3"]:
            physics = tp.Physics()
            physics.cushion = cushion
            physics.friction = friction
            shot = tp.simulate(balls, strike, physics=physics)
            seen.add(shot.ball(0).position)
    assert len(seen) == 6


def test_sampled_motion_agrees_with_the_events_and_the_end():
    shot = tp.simulate(tp.rack("9ball"), tp.Strike(7, 0, 0, 0.2))
    times = [0.0] + [e.time for e in shot.events] + [shot.rest_time + 1]
    sample = shot.sample(times)
    n = len(sample["id"])
    assert sample["position"].shape == (len(times), n, 2)
    assert sample["angular_velocity"].shape == (len(times), n, 3)
    last = {int(i): tuple(p) for i, p in zip(sample["id"], sample["position"][-1])}
    for ball in shot.balls:
        assert last[ball.id] == ball.position
    assert (sample["velocity"][-1] == 0).all()


def test_event_state_gives_the_collision():
    shot = tp.simulate([tp.Ball(0, 0.6, 0.635), tp.Ball(1, 1.2, 0.635)], tp.Strike(2, 0))
    index = next(i for i, e in enumerate(shot.events) if e.kind == "ball-ball")
    state = shot.event_state(index)
    assert state.ball_before.position == state.ball_after.position
    assert state.other_before.velocity == (0.0, 0.0)
    assert state.other_after.velocity[0] > 1.0
    # A straight hit: the cue ball keeps little of its speed, the object ball takes the rest.
    assert abs(state.ball_after.velocity[0]) < 0.2 * state.ball_before.velocity[0]
    gap = state.other_before.position[0] - state.ball_before.position[0]
    assert gap == pytest.approx(2 * 0.028575, abs=1e-12)
    with pytest.raises(IndexError):
        shot.event_state(len(shot.events))


def test_world_steps_to_the_same_end_as_simulate():
    balls = tp.rack("8ball")
    world = tp.World(balls)
    world.strike(tp.Strike(8, 1))
    events = []
    while (event := world.step()) is not None:
        events.append((event.time, event.kind, event.ball, event.other))
    shot = tp.simulate(balls, tp.Strike(8, 1), trajectory=False)
    assert events == [(e.time, e.kind, e.ball, e.other) for e in shot.events]
    assert world.at_rest
    assert sorted(world.balls, key=lambda b: b.id) == sorted(shot.balls, key=lambda b: b.id)


def test_many_shots_on_threads_are_the_shots_one_at_a_time():
    balls = tp.rack("8ball", seed=7)
    strikes = [tp.Strike(1 + i % 8, i * 7.3, 0.1, -0.1) for i in range(64)]
    many = tp.simulate_many(balls, strikes, threads=4)
    for strike, shot in zip(strikes, many):
        one = tp.simulate(balls, strike, trajectory=False)
        assert one.balls == shot.balls and one.rest_time == shot.rest_time
    layouts = [balls] * len(strikes)
    assert [s.balls for s in tp.simulate_many(layouts, strikes, threads=3)] == \
        [s.balls for s in many]
    with pytest.raises(ValueError, match="shot 1: speed 25"):
        tp.simulate_many(balls, [tp.Strike(1), tp.Strike(25)])


def test_a_game_of_nine_ball_follows_the_rules():
    game = tp.Game("9ball", seed=3)
    assert game.legal_targets() == [1]
    assert game.ball_in_hand == "kitchen"
    # A break that goes away from the rack and touches nothing: the cue ball hits no ball.
    verdict, shot = game.play(tp.Strike(0.3, 180))
    assert verdict.foul == "no-contact" and verdict.first_contact == -1
    assert "bad-break" in verdict.fouls
    assert game.shooter == 2 and game.ball_in_hand == "anywhere"
    assert game.legal_targets() == [1]
    with pytest.raises(ValueError):
        game.place_cue_ball(-5, -5)
    x, y = game.legal_placements(4)[0]
    game.place_cue_ball(x, y)
    assert game.balls[0].position == (x, y)
    # The game's physics and table are copies: changing them changes nothing.
    physics = game.physics
    physics["u_s"] = 0.9
    assert game.physics["u_s"] == 0.2


def test_bad_input_is_refused_in_words():
    with pytest.raises(ValueError, match="must be finite"):
        tp.simulate([tp.Ball(0, 1, 0.6, vx=float("nan"))], tp.Strike(1))
    with pytest.raises(ValueError, match="faster than 20"):
        tp.simulate([tp.Ball(0, 1, 0.6), tp.Ball(1, 2, 0.6, vx=1e300)], tp.Strike(1))
    with pytest.raises(ValueError, match="mass must be > 0"):
        tp.simulate([tp.Ball(0, 1, 0.6, mass=-1)], tp.Strike(1))
    with pytest.raises(ValueError, match="stationary but has a velocity"):
        tp.simulate([tp.Ball(0, 1, 0.6), tp.Ball(1, 2, 0.6, vx=1, state="stationary")],
                    tp.Strike(1))
    with pytest.raises(ValueError, match="no cue ball"):
        tp.simulate([tp.Ball(1, 1, 0.6)], tp.Strike(1))
    with pytest.raises(ValueError, match="decay rate K must be > 0"):
        tp.Physics().friction = "decay 0"
    with pytest.raises(ValueError, match="cushion_height_ratio"):
        tp.Physics().cushion_height_ratio = float("nan")
    with pytest.raises(ValueError, match=">= 0"):
        tp.simulate(tp.rack("8ball"), tp.Strike(1)).sample([-1])
    with pytest.raises(TypeError, match="list of Balls"):
        tp.simulate_many([tp.Ball(0, 1, 0.6), [tp.Ball(0, 1, 0.6)]], [tp.Strike(1)] * 2)
    with pytest.raises(ValueError, match="breaker"):
        tp.Match("9ball", breaker=3)
    physics = tp.Physics()
    physics["R"] = 0.5
    with pytest.raises(ValueError, match="rack does not fit"):
        tp.Game("8ball", physics=physics)
    # A ball given its motion without a state is sliding; one turning on the spot spins.
    assert tp.Ball(1, 1, 0.6, vx=1).state == "sliding"
    assert tp.Ball(1, 1, 0.6, wz=5).state == "spinning"
    moving = tp.simulate([tp.Ball(0, 1, 0.6), tp.Ball(1, 2, 0.6, vx=1)], tp.Strike(0))
    # Sent at 1 m/s towards the foot rail 0.51 m away: it reaches it and comes back.
    assert any(e.kind == "cushion" and e.ball == 1 for e in moving.events)


def test_too_many_balls_for_threads_is_an_error_not_a_crash():
    # One more ball than a table holds: refused before any thread starts.
    balls = [tp.Ball(0, 0.05, 0.05)] + [tp.Ball(i, 0.1 + (i % 1000) * 0.06,
                                                 0.1 + (i // 1000) * 0.06)
                                        for i in range(1, 32770)]
    table = tp.Table.custom(70, 70)
    with pytest.raises(ValueError, match="more than the 32768"):
        tp.simulate_many(balls, [tp.Strike(1)] * 2, table, threads=2)


def test_computer_plays_a_whole_match_and_the_record_replays(tmp_path):
    match = tp.Match("8ball", names=("Ada", "Bob"), computers=("hard", "pro"), seed=4)
    for _ in range(400):
        if match.pending()["kind"] == "over":
            break
        match.play_computer()
    assert match.pending()["kind"] == "over"
    assert match.game.winner in (1, 2)
    again = tp.Match.replay(match.record())
    assert again.state_hash == match.state_hash
    with pytest.raises(ValueError, match="line"):
        tp.Match.replay(match.record().replace("shot ", "shot x", 1))


def test_a_match_refuses_what_is_not_its_turn():
    match = tp.Match("9ball")
    assert match.pending() == {"kind": "place", "player": 1, "ball_in_hand": "kitchen",
                               "choices": []}
    with pytest.raises(ValueError):
        match.shoot(2, tp.Strike(5))
    with pytest.raises(ValueError, match="outside"):
        match.shoot(1, tp.Strike(50))
    played = match.shoot(1, tp.Strike(8))
    assert played.was_break and played.shooter == 1
    # The match's game is a copy: playing it does not move the match.
    before = match.state_hash
    copy = match.game
    if copy.ready_to_shoot():
        copy.play(tp.Strike(3))
    assert match.state_hash == before


def test_without_numpy_arrays_are_lists():
    code = ("import sys; sys.modules['numpy'] = None\n"
            "import termpool as tp\n"
            "s = tp.simulate(tp.rack('8ball'), tp.Strike(5)).sample([0, 1])\n"
            "assert not tp.numpy and isinstance(s['position'], list)\n"
            "assert len(s['position']) == 2 and len(s['position'][0][0]) == 2\n")
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr


def test_the_worked_example_reproduces_experiment_throw():
    """doc/python.md's example gives `termpool experiment throw`'s figures."""
    sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "doc", "examples"))
    import throw

    csv = subprocess.run([BIN, "experiment", "throw", "--csv"], capture_output=True,
                         text=True).stdout.splitlines()
    rows = [line.split(",") for line in csv[1:]]
    checked = 0
    for cue, speed, cut, figure in rows:
        if (cue, speed) in (("stun", "0.3"), ("rolling", "2")):
            mine = throw.throw_deg(float(speed), float(cut), rolling=cue == "rolling")
            assert mine == pytest.approx(float(figure), abs=1e-7), (cue, speed, cut)
            checked += 1
    assert checked == 2 * 61
