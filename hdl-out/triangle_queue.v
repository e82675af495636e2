

module triangle_queue(clock,inp$valid,inp$ready,inp$v0_x,inp$v0_y,inp$v0_z,inp$v0_c0,inp$v0_c1,inp$v0_c2,inp$v0_iw,inp$v1_x,inp$v1_y,inp$v1_z,inp$v1_c0,inp$v1_c1,inp$v1_c2,inp$v1_iw,inp$v2_x,inp$v2_y,inp$v2_z,inp$v2_c0,inp$v2_c1,inp$v2_c2,inp$v2_iw,out$valid,out$ready,out$v0_x,out$v0_y,out$v0_z,out$v0_c0,out$v0_c1,out$v0_c2,out$v0_iw,out$v1_x,out$v1_y,out$v1_z,out$v1_c0,out$v1_c1,out$v1_c2,out$v1_iw,out$v2_x,out$v2_y,out$v2_z,out$v2_c0,out$v2_c1,out$v2_c2,out$v2_iw,idle);
    
    // Module arguments
    input wire  clock;
    input wire  inp$valid;
    output reg  inp$ready;
    input wire  [15:0] inp$v0_x;
    input wire  [15:0] inp$v0_y;
    input wire  [17:0] inp$v0_z;
    input wire  [7:0] inp$v0_c0;
    input wire  [7:0] inp$v0_c1;
    input wire  [7:0] inp$v0_c2;
    input wire  [15:0] inp$v0_iw;
    input wire  [15:0] inp$v1_x;
    input wire  [15:0] inp$v1_y;
    input wire  [17:0] inp$v1_z;
    input wire  [7:0] inp$v1_c0;
    input wire  [7:0] inp$v1_c1;
    input wire  [7:0] inp$v1_c2;
    input wire  [15:0] inp$v1_iw;
    input wire  [15:0] inp$v2_x;
    input wire  [15:0] inp$v2_y;
    input wire  [17:0] inp$v2_z;
    input wire  [7:0] inp$v2_c0;
    input wire  [7:0] inp$v2_c1;
    input wire  [7:0] inp$v2_c2;
    input wire  [15:0] inp$v2_iw;
    output reg  out$valid;
    input wire  out$ready;
    output reg  [15:0] out$v0_x;
    output reg  [15:0] out$v0_y;
    output reg  [17:0] out$v0_z;
    output reg  [7:0] out$v0_c0;
    output reg  [7:0] out$v0_c1;
    output reg  [7:0] out$v0_c2;
    output reg  [15:0] out$v0_iw;
    output reg  [15:0] out$v1_x;
    output reg  [15:0] out$v1_y;
    output reg  [17:0] out$v1_z;
    output reg  [7:0] out$v1_c0;
    output reg  [7:0] out$v1_c1;
    output reg  [7:0] out$v1_c2;
    output reg  [15:0] out$v1_iw;
    output reg  [15:0] out$v2_x;
    output reg  [15:0] out$v2_y;
    output reg  [17:0] out$v2_z;
    output reg  [7:0] out$v2_c0;
    output reg  [7:0] out$v2_c1;
    output reg  [7:0] out$v2_c2;
    output reg  [15:0] out$v2_iw;
    output reg  idle;
    
    // Constant declarations
    localparam  depth = 16'h200;
    localparam  at_y = 16'h10;
    localparam  at_z = 16'h20;
    localparam  at_c0 = 16'h32;
    localparam  at_c1 = 16'h3a;
    localparam  at_c2 = 16'h42;
    localparam  at_iw = 16'h4a;
    
    // Stub signals
    reg  [8:0] v0_ram$read_address;
    reg  v0_ram$read_clock;
    wire  [89:0] v0_ram$read_data;
    reg  [8:0] v0_ram$write_address;
    reg  v0_ram$write_clock;
    reg  [89:0] v0_ram$write_data;
    reg  v0_ram$write_enable;
    reg  [8:0] v1_ram$read_address;
    reg  v1_ram$read_clock;
    wire  [89:0] v1_ram$read_data;
    reg  [8:0] v1_ram$write_address;
    reg  v1_ram$write_clock;
    reg  [89:0] v1_ram$write_data;
    reg  v1_ram$write_enable;
    reg  [8:0] v2_ram$read_address;
    reg  v2_ram$read_clock;
    wire  [89:0] v2_ram$read_data;
    reg  [8:0] v2_ram$write_address;
    reg  v2_ram$write_clock;
    reg  [89:0] v2_ram$write_data;
    reg  v2_ram$write_enable;
    reg  [8:0] wr$d;
    wire  [8:0] wr$q;
    reg  wr$clock;
    reg  [8:0] rd$d;
    wire  [8:0] rd$q;
    reg  rd$clock;
    reg  [15:0] level$d;
    wire  [15:0] level$q;
    reg  level$clock;
    reg  fresh$d;
    wire  fresh$q;
    reg  fresh$clock;
    
    // Local signals
    reg  push;
    reg  pop;
    reg  [8:0] read_at;
    
    // Sub module instances
    triangle_queue$v0_ram v0_ram(
        .read_address(v0_ram$read_address),
        .read_clock(v0_ram$read_clock),
        .read_data(v0_ram$read_data),
        .write_address(v0_ram$write_address),
        .write_clock(v0_ram$write_clock),
        .write_data(v0_ram$write_data),
        .write_enable(v0_ram$write_enable)
    );
    triangle_queue$v1_ram v1_ram(
        .read_address(v1_ram$read_address),
        .read_clock(v1_ram$read_clock),
        .read_data(v1_ram$read_data),
        .write_address(v1_ram$write_address),
        .write_clock(v1_ram$write_clock),
        .write_data(v1_ram$write_data),
        .write_enable(v1_ram$write_enable)
    );
    triangle_queue$v2_ram v2_ram(
        .read_address(v2_ram$read_address),
        .read_clock(v2_ram$read_clock),
        .read_data(v2_ram$read_data),
        .write_address(v2_ram$write_address),
        .write_clock(v2_ram$write_clock),
        .write_data(v2_ram$write_data),
        .write_enable(v2_ram$write_enable)
    );
    triangle_queue$wr wr(
        .d(wr$d),
        .q(wr$q),
        .clock(wr$clock)
    );
    triangle_queue$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    triangle_queue$level level(
        .d(level$d),
        .q(level$q),
        .clock(level$clock)
    );
    triangle_queue$fresh fresh(
        .d(fresh$d),
        .q(fresh$q),
        .clock(fresh$clock)
    );
    
    // Update code
    always @(*) begin
        wr$clock = clock;
        rd$clock = clock;
        level$clock = clock;
        fresh$clock = clock;
        wr$d = wr$q;
        rd$d = rd$q;
        level$d = level$q;
        fresh$d = fresh$q;
        v0_ram$read_clock = clock;
        v0_ram$write_clock = clock;
        v1_ram$read_clock = clock;
        v1_ram$write_clock = clock;
        v2_ram$read_clock = clock;
        v2_ram$write_clock = clock;
        inp$ready = level$q < depth;
        out$valid = |level$q & ~(fresh$q & (level$q == 32'h1));
        idle = ~|level$q;
        push = inp$valid & inp$ready;
        pop = out$valid & out$ready;
        fresh$d = push;
        if (push) begin
            wr$d = wr$q + 32'h1;
        end
        if (pop) begin
            rd$d = rd$q + 32'h1;
        end
        if (push & ~pop) begin
            level$d = level$q + 32'h1;
        end
        if (~push & pop) begin
            level$d = level$q - 32'h1;
        end
        v0_ram$write_enable = push;
        v1_ram$write_enable = push;
        v2_ram$write_enable = push;
        v0_ram$write_address = wr$q;
        v1_ram$write_address = wr$q;
        v2_ram$write_address = wr$q;
        v0_ram$write_data = ((inp$v0_x) & 90'h3ffffffffffffffffffffff) | (((inp$v0_y) & 90'h3ffffffffffffffffffffff) << at_y) | (((inp$v0_z) & 90'h3ffffffffffffffffffffff) << at_z) | (((inp$v0_c0) & 90'h3ffffffffffffffffffffff) << at_c0) | (((inp$v0_c1) & 90'h3ffffffffffffffffffffff) << at_c1) | (((inp$v0_c2) & 90'h3ffffffffffffffffffffff) << at_c2) | (((inp$v0_iw) & 90'h3ffffffffffffffffffffff) << at_iw);
        v1_ram$write_data = ((inp$v1_x) & 90'h3ffffffffffffffffffffff) | (((inp$v1_y) & 90'h3ffffffffffffffffffffff) << at_y) | (((inp$v1_z) & 90'h3ffffffffffffffffffffff) << at_z) | (((inp$v1_c0) & 90'h3ffffffffffffffffffffff) << at_c0) | (((inp$v1_c1) & 90'h3ffffffffffffffffffffff) << at_c1) | (((inp$v1_c2) & 90'h3ffffffffffffffffffffff) << at_c2) | (((inp$v1_iw) & 90'h3ffffffffffffffffffffff) << at_iw);
        v2_ram$write_data = ((inp$v2_x) & 90'h3ffffffffffffffffffffff) | (((inp$v2_y) & 90'h3ffffffffffffffffffffff) << at_y) | (((inp$v2_z) & 90'h3ffffffffffffffffffffff) << at_z) | (((inp$v2_c0) & 90'h3ffffffffffffffffffffff) << at_c0) | (((inp$v2_c1) & 90'h3ffffffffffffffffffffff) << at_c1) | (((inp$v2_c2) & 90'h3ffffffffffffffffffffff) << at_c2) | (((inp$v2_iw) & 90'h3ffffffffffffffffffffff) << at_iw);
        read_at = rd$q;
        if (pop) begin
            read_at = rd$q + 32'h1;
        end
        v0_ram$read_address = read_at;
        v1_ram$read_address = read_at;
        v2_ram$read_address = read_at;
        out$v0_x = v0_ram$read_data[(32'h0)+:(16)];
        out$v0_y = v0_ram$read_data[(at_y)+:(16)];
        out$v0_z = v0_ram$read_data[(at_z)+:(18)];
        out$v0_c0 = v0_ram$read_data[(at_c0)+:(8)];
        out$v0_c1 = v0_ram$read_data[(at_c1)+:(8)];
        out$v0_c2 = v0_ram$read_data[(at_c2)+:(8)];
        out$v0_iw = v0_ram$read_data[(at_iw)+:(16)];
        out$v1_x = v1_ram$read_data[(32'h0)+:(16)];
        out$v1_y = v1_ram$read_data[(at_y)+:(16)];
        out$v1_z = v1_ram$read_data[(at_z)+:(18)];
        out$v1_c0 = v1_ram$read_data[(at_c0)+:(8)];
        out$v1_c1 = v1_ram$read_data[(at_c1)+:(8)];
        out$v1_c2 = v1_ram$read_data[(at_c2)+:(8)];
        out$v1_iw = v1_ram$read_data[(at_iw)+:(16)];
        out$v2_x = v2_ram$read_data[(32'h0)+:(16)];
        out$v2_y = v2_ram$read_data[(at_y)+:(16)];
        out$v2_z = v2_ram$read_data[(at_z)+:(18)];
        out$v2_c0 = v2_ram$read_data[(at_c0)+:(8)];
        out$v2_c1 = v2_ram$read_data[(at_c1)+:(8)];
        out$v2_c2 = v2_ram$read_data[(at_c2)+:(8)];
        out$v2_iw = v2_ram$read_data[(at_iw)+:(16)];
    end
    
endmodule // triangle_queue


module triangle_queue$fresh(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // triangle_queue$fresh


module triangle_queue$level(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // triangle_queue$level


module triangle_queue$rd(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // triangle_queue$rd


module triangle_queue$v0_ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [8:0] read_address;
    input wire  read_clock;
    output reg  [89:0] read_data;
    input wire  [8:0] write_address;
    input wire  write_clock;
    input wire  [89:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[89:0] mem[511:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // triangle_queue$v0_ram


module triangle_queue$v1_ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [8:0] read_address;
    input wire  read_clock;
    output reg  [89:0] read_data;
    input wire  [8:0] write_address;
    input wire  write_clock;
    input wire  [89:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[89:0] mem[511:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // triangle_queue$v1_ram


module triangle_queue$v2_ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [8:0] read_address;
    input wire  read_clock;
    output reg  [89:0] read_data;
    input wire  [8:0] write_address;
    input wire  write_clock;
    input wire  [89:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[89:0] mem[511:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // triangle_queue$v2_ram


module triangle_queue$wr(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // triangle_queue$wr
