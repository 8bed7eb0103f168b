"""Flat-pack furniture (thesis ch. 5): master boards, boards, layouts and their cut sheets."""
