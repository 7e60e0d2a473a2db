"""The robot module's ActionCommand carries a team message as bytes."""
import robot


def test_team_message_is_bytes_both_ways():
    request = robot.All()
    assert request.teamMessage == b""
    request.teamMessage = b"\x00\xffball at 1200"
    assert request.teamMessage == b"\x00\xffball at 1200"
