// Deliberately misformatted: the format check must reject this file.
int  answer( ) {return 42 ;}
