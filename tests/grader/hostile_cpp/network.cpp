// expect: RE
// No network: connecting anywhere fails (exit code 3); a connection would print nothing (PE).
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>
int main() {
    const char* hosts[] = {"1.1.1.1", "8.8.8.8", "127.0.0.1"};
    for (const char* h : hosts) {
        int s = socket(AF_INET, SOCK_STREAM, 0);
        if (s < 0) continue;
        sockaddr_in a{};
        a.sin_family = AF_INET;
        a.sin_port = htons(80);
        inet_pton(AF_INET, h, &a.sin_addr);
        if (connect(s, (sockaddr*)&a, sizeof a) == 0) return 0;
        close(s);
    }
    return 3;
}
