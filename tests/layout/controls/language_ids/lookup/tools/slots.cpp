int slots(bool python) { return run_slots(*language_named("python")); }
