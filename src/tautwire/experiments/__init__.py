"""Reproductions of the paper's figures and tables, and synthetic runs with known truth."""
