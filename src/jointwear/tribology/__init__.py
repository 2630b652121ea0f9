"""Tribology: sliding, Archard wear and wear metrics."""
