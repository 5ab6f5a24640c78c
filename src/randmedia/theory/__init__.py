"""Closed-form results used as exact references and as the papers' formulas."""
