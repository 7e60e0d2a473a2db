"""Touchline match viewer: a 2D-canvas web page fed over a WebSocket from live LCM or a log."""
