"""Plots (matplotlib, headless Agg backend) and video of tautwire runs."""
