"""The timeline's markers: goals, penalties and falls from the match events, and a marker for
each change of the game state (or of the half), by time; other events make none."""
from touchline_viewer.timeline import timeline


def game(t: float, state: int, first_half: bool = True) -> dict:
    return {"utime": round(t * 1e6), "state": state, "first_half": first_half}


def event(t: float, kind: str, team: int = 0, player: int = 0, text: str = "") -> dict:
    return {"utime": round(t * 1e6), "kind": kind, "team": team, "player": player, "text": text}


def test_state_changes_are_marked_once_each():
    games = [game(0, 0), game(1, 0), game(2, 1), game(3, 1), game(4, 3), game(600, 0, False), game(601, 0, False)]
    marks = timeline(games, [])
    assert [(m["t"], m["kind"], m["text"]) for m in marks] == [
        (0, "state", "INITIAL, 1st half"), (2, "state", "READY, 1st half"), (4, "state", "PLAYING, 1st half"),
        (600, "state", "INITIAL, 2nd half")]


def test_goals_penalties_and_falls_are_marked_with_who():
    events = [event(5, "GOAL", 1, 3, "goal"), event(2, "PENALTY", 0, 2, "pushing"), event(3, "FALL", 1, 1, "fell"),
              event(4, "BALL_OUT"), event(4.5, "STATE_CHANGE", -1, 0, "READY")]
    marks = timeline([], events)
    assert [(m["t"], m["kind"], m["team"], m["player"], m["text"]) for m in marks] == [
        (2, "penalty", 0, 2, "pushing"), (3, "fall", 1, 1, "fell"), (5, "goal", 1, 3, "goal")]


def test_markers_are_in_time_order_across_sources():
    marks = timeline([game(0, 3), game(10, 4)], [event(5, "GOAL", 0, 2)])
    assert [m["kind"] for m in marks] == ["state", "goal", "state"]
