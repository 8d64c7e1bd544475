"""Manipulation primitives A-I: small state machines from Observation to Command."""
