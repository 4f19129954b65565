// A fixture of tests/architecture: a module testing another module's name.
bool closes(const Scene& scene) { return scene.has_physics("mechanics"); }
