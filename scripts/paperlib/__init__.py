"""Reproductions of the four papers' experiments through asv_batch (scripts/papers.py)."""
