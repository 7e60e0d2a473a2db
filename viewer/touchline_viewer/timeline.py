"""The replay's timeline: a marker for each goal, penalty and fall (TL_EVENT) and each change of
the game state (TL_GAME: the state as the robots are told it, so a GameController-driven match
gets its markers too), in sim time, for the strip under the field."""

GAME_STATES = {0: "INITIAL", 1: "READY", 2: "SET", 3: "PLAYING", 4: "FINISHED", 5: "STANDBY"}
EVENT_MARKERS = {"GOAL": "goal", "PENALTY": "penalty", "FALL": "fall"}  # TL_EVENT kind -> marker kind


def timeline(games: list, events: list) -> list:
    """Markers {t (s), kind: goal | penalty | fall | state, team, player, text} by time, from
    game states and match events sorted by utime."""
    markers, state = [], None
    for g in games:
        half = (g["state"], g["first_half"])
        if half != state:
            name = GAME_STATES.get(g["state"], str(g["state"]))
            markers.append({"t": g["utime"] / 1e6, "kind": "state", "team": -1, "player": 0,
                            "text": f"{name}, {'1st' if g['first_half'] else '2nd'} half"})
            state = half
    for e in events:
        kind = EVENT_MARKERS.get(e["kind"])
        if kind:
            markers.append({"t": e["utime"] / 1e6, "kind": kind, "team": e["team"], "player": e["player"],
                            "text": e["text"]})
    return sorted(markers, key=lambda m: m["t"])
