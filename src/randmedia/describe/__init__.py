"""Structural descriptors of configurations, returned as xarray Datasets."""
