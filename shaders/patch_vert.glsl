// One vertex per patch; the control shader reads the plan by gl_PrimitiveID.
void main() {}
