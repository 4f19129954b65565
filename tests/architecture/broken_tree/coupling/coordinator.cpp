// A fixture of tests/architecture: the coordinator naming a physics field.
double flow_heads(double pressure) { return pressure; }
