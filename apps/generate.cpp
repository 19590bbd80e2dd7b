// Interim entry point while the engine is being assembled; replaced by the real CLI.
int main() { return 0; }
