"""Behaviour skills: small classes with tick(blackboard) -> robot.All, composed.

Each module has a line-by-line C++ port in behaviour_cpp/.../skills/ with the same
names and constants, so both give the same ActionCommand for the same Blackboards.
"""
