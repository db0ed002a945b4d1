// BREAKS: src/tools has no layer rule
int main() { return 0; }
