"""The ground floor: reading and writing files safely, bytes to text, findings, and how values are shown.

Nothing here knows what a CNC list is; every other stage builds on it.
"""
